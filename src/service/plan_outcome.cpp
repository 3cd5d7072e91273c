#include "plan_outcome.hpp"

namespace eaci_service {

const char* toString(PlanOutcome outcome) {
  switch (outcome) {
    case PlanOutcome::kOk: return "ok";
    case PlanOutcome::kStartOffMap: return "start off the map";
    case PlanOutcome::kStartBlocked: return "start blocked";
    case PlanOutcome::kGoalOffMap: return "goal off the map";
    case PlanOutcome::kGoalBlocked: return "goal blocked";
    case PlanOutcome::kNoPath: return "no path";
    case PlanOutcome::kTimeLimit: return "time limit";
    case PlanOutcome::kCancelled: return "cancelled";
    case PlanOutcome::kShutdown: return "shutting down";
    case PlanOutcome::kBadParameters: return "bad parameters";
    case PlanOutcome::kNotInitialised: return "not initialised";
    case PlanOutcome::kBadCostmap: return "bad costmap";
    case PlanOutcome::kInternalError: return "internal error";
  }
  return "?";
}

const char* toName(PlanOutcome outcome) {
  switch (outcome) {
    case PlanOutcome::kOk: return "ok";
    case PlanOutcome::kStartOffMap: return "start_off_map";
    case PlanOutcome::kStartBlocked: return "start_blocked";
    case PlanOutcome::kGoalOffMap: return "goal_off_map";
    case PlanOutcome::kGoalBlocked: return "goal_blocked";
    case PlanOutcome::kNoPath: return "no_path";
    case PlanOutcome::kTimeLimit: return "time_limit";
    case PlanOutcome::kCancelled: return "cancelled";
    case PlanOutcome::kShutdown: return "shutdown";
    case PlanOutcome::kBadParameters: return "bad_parameters";
    case PlanOutcome::kNotInitialised: return "not_initialised";
    case PlanOutcome::kBadCostmap: return "bad_costmap";
    case PlanOutcome::kInternalError: return "internal_error";
  }
  return "?";
}

}  // namespace eaci_service
