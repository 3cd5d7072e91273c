// What the planner node and the move_base plugin share: a plan request on a grid view in a
// map frame, checked and answered with a nav_msgs/Path or a one-line reason.
#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Path.h>

#include <atomic>
#include <string>
#include <vector>

#include "eaci/planner.hpp"
#include "grid_conversion.hpp"
#include "ros_parameters.hpp"

namespace eaci_ros {

// Why a colony stopped before its iterations were done.
enum class StopReason { kNone, kTimeLimit, kCancelled, kShutdown };
const char* toString(StopReason reason);

struct GridPlan {
  bool ok = false;
  std::string error;          // one line when !ok
  nav_msgs::Path path;        // in the map frame; empty when !ok
  eaci::PlanResult result;    // the core's result (pheromone filled if asked for)
  StopReason stopped_by = StopReason::kNone;  // set when the colony was interrupted
};

// Plans from `start` to `goal` (positions in `frame`, frame ids already checked) on `view`:
// start off the map or in an obstacle, goal off the map or in an obstacle beyond
// `tolerance` metres, no route, or no route before the colony was stopped -> !ok with the reason.
// The colony is stopped between two iterations, and the best route so far returned, when
// max_planning_time runs out, when `*cancel` becomes true (the ~cancel services), or when ROS
// shuts down (ros::ok() false or a shutdown requested). `workspace`: the planner's
// buffers and threads, kept by the caller from plan to plan (eaci::PlanOptions::workspace),
// which keeps options.landmarks landmarks too.
GridPlan planOnGrid(const eaci::GridView& view, const MapFrame& frame, const geometry_msgs::PoseStamped& start,
                    const geometry_msgs::PoseStamped& goal, double tolerance, const eaci::Parameters& params,
                    const RosPlannerOptions& options, const std::atomic<bool>* cancel = nullptr,
                    eaci::PlannerWorkspace* workspace = nullptr);

}  // namespace eaci_ros
