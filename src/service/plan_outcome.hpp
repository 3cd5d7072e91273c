// Why a plan ended as it did: one typed outcome from the planning service to every adapter
// (the move_base plugin logs it, the Move Base Flex planner maps it to mbf_msgs/GetPath's codes,
// the node and ~make_plan log it, the CLI's exit code and JSON carry it). No adapter decides
// anything from the reply's sentence.
#pragma once

namespace eaci_service {

enum class PlanOutcome {
  kOk,              // a route (possibly the best so far when a stop came after one was found)
  kStartOffMap,     // the start lies off the costmap
  kStartBlocked,    // the start is in an obstacle (lethal), with no way out of the inflated band
  kGoalOffMap,      // the goal lies off the costmap
  kGoalBlocked,     // the goal is in an obstacle and no reachable cell lies within the tolerance
  kNoPath,          // start and goal are free but no route joins them
  kTimeLimit,       // max_planning_time ran out before a route was found
  kCancelled,       // cancel() before a route was found
  kShutdown,        // the process is shutting down
  kBadParameters,   // the parameters in force are refused (named in the message)
  kNotInitialised,  // the planner was never set up (the adapters' own)
  kBadCostmap,      // the costmap is empty, too large, or not what it claims to be
  kInternalError,   // out of memory, an exception, a route that failed the last check
};

// A short lower-case name for log lines: "ok", "start off the map", ...
const char* toString(PlanOutcome outcome);
// A stable snake_case word for machines (JSON, tests): "ok", "start_off_map", "no_path", ...
const char* toName(PlanOutcome outcome);

}  // namespace eaci_service
