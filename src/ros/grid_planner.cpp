#include "grid_planner.hpp"

#include <ros/ros.h>

#include <Eigen/Core>

#include "eaci/grid/nearest_free.hpp"

#include <chrono>
#include <cstdio>

namespace eaci_ros {
namespace {

std::string where(const geometry_msgs::PoseStamped& pose) {
  char text[96];
  std::snprintf(text, sizeof(text), "(%.3f, %.3f)", pose.pose.position.x, pose.pose.position.y);
  return text;
}

GridPlan failed(const std::string& error) {
  GridPlan plan;
  plan.error = error;
  return plan;
}

}  // namespace

const char* toString(StopReason reason) {
  switch (reason) {
    case StopReason::kNone: return "not stopped";
    case StopReason::kTimeLimit: return "max_planning_time ran out";
    case StopReason::kCancelled: return "cancelled";
    case StopReason::kShutdown: return "ROS is shutting down";
  }
  return "?";
}

GridPlan planOnGrid(const eaci::GridView& view, const MapFrame& frame, const geometry_msgs::PoseStamped& start,
                    const geometry_msgs::PoseStamped& goal, double tolerance, const eaci::Parameters& params,
                    const RosPlannerOptions& options, const std::atomic<bool>* cancel,
                    eaci::PlannerWorkspace* workspace) {
  if (view.empty()) return failed("the map is empty");
  const auto start_cell = frame.worldToCell({start.pose.position.x, start.pose.position.y});
  if (!start_cell) return failed("start " + where(start) + " is off the map");
  if (view.isObstacle(*start_cell)) return failed("start " + where(start) + " is in an obstacle");
  const auto goal_cell = frame.worldToCell({goal.pose.position.x, goal.pose.position.y});
  if (!goal_cell) return failed("goal " + where(goal) + " is off the map");
  const auto reachable_goal = eaci::nearestFreeCell(view, *goal_cell, tolerance / frame.resolution);
  if (!reachable_goal) {
    char reason[160];
    std::snprintf(reason, sizeof(reason), "goal %s is in an obstacle and no free cell lies within %.3f m of it",
                  where(goal).c_str(), tolerance);
    return failed(reason);
  }

  eaci::PlanOptions plan_options;
  plan_options.record_pheromone = options.visualize_pheromone;
  plan_options.workspace = workspace;
  if (workspace != nullptr) workspace->search.useLandmarks(options.landmarks);
  const bool timed = options.max_planning_time > 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timed ? options.max_planning_time : 0.0);
  StopReason stopped_by = StopReason::kNone;
  // Asked between EACI's set-up steps and between iterations, in this thread.
  plan_options.should_stop = [&](int) {
    if (!ros::ok() || ros::isShuttingDown()) stopped_by = StopReason::kShutdown;
    else if (cancel != nullptr && cancel->load()) stopped_by = StopReason::kCancelled;
    else if (timed && std::chrono::steady_clock::now() >= deadline) stopped_by = StopReason::kTimeLimit;
    return stopped_by != StopReason::kNone;
  };
  GridPlan plan;
  plan.result = eaci::plan(view, *start_cell, *reachable_goal, options.algorithm, params, plan_options);
  if (plan.result.interrupted) plan.stopped_by = stopped_by;
  if (!plan.result.success()) {
    if (!plan.result.interrupted) {
      plan.error = plan.result.error;
    } else if (stopped_by == StopReason::kTimeLimit) {
      plan.error = "no route found within max_planning_time";
    } else {
      plan.error = std::string(toString(stopped_by)) + " after " + std::to_string(plan.result.iterations_run) +
                   " iterations, before any ant reached the goal: no route";
    }
    return plan;
  }
  geometry_msgs::PoseStamped target = goal;
  if (!(*reachable_goal == *goal_cell)) {
    const Eigen::Vector2d centre = frame.cellToWorld(*reachable_goal);
    target.pose.position.x = centre.x();
    target.pose.position.y = centre.y();
  }
  plan.path = toPath(plan.result.smoothed_path, frame, start, target, ros::Time::now(), options.orientation_mode);
  plan.ok = true;
  return plan;
}

}  // namespace eaci_ros
