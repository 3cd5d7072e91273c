#include "mbf_outcome.hpp"

#include <mbf_msgs/GetPathResult.h>

namespace eaci_ros {

std::uint32_t mbfOutcome(eaci_service::PlanOutcome outcome) noexcept {
  using eaci_service::PlanOutcome;
  using Result = mbf_msgs::GetPathResult;
  switch (outcome) {
    case PlanOutcome::kOk: return Result::SUCCESS;
    case PlanOutcome::kStartOffMap: return Result::OUT_OF_MAP;
    case PlanOutcome::kGoalOffMap: return Result::OUT_OF_MAP;  // as global_planner's and navfn's MBF wrappers
    case PlanOutcome::kStartBlocked: return Result::INVALID_START;
    case PlanOutcome::kGoalBlocked: return Result::INVALID_GOAL;
    case PlanOutcome::kNoPath: return Result::NO_PATH_FOUND;
    case PlanOutcome::kTimeLimit: return Result::PAT_EXCEEDED;  // the planner's own max_planning_time
    case PlanOutcome::kCancelled: return Result::CANCELED;
    case PlanOutcome::kShutdown: return Result::STOPPED;
    case PlanOutcome::kBadParameters: return kMbfBadParameters;
    case PlanOutcome::kNotInitialised: return Result::NOT_INITIALIZED;
    case PlanOutcome::kBadCostmap: return Result::MAP_ERROR;
    case PlanOutcome::kInternalError: return Result::INTERNAL_ERROR;
  }
  return Result::INTERNAL_ERROR;  // a value outside the enum
}

}  // namespace eaci_ros
