#include "grid_planner.hpp"

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

GridPlan planOnGrid(const eaci::GridView& view, const MapFrame& frame, const geometry_msgs::PoseStamped& start,
                    const geometry_msgs::PoseStamped& goal, double tolerance, const eaci::Parameters& params,
                    const RosPlannerOptions& options) {
  if (view.empty()) return failed("the map is empty");
  const auto start_cell = cellAt(frame, start.pose.position.x, start.pose.position.y);
  if (!start_cell) return failed("start " + where(start) + " is off the map");
  if (view.isObstacle(*start_cell)) return failed("start " + where(start) + " is in an obstacle");
  const auto goal_cell = cellAt(frame, goal.pose.position.x, goal.pose.position.y);
  if (!goal_cell) return failed("goal " + where(goal) + " is off the map");
  const auto reachable_goal = nearestFreeCell(view, *goal_cell, tolerance / frame.resolution);
  if (!reachable_goal) {
    char reason[160];
    std::snprintf(reason, sizeof(reason), "goal %s is in an obstacle and no free cell lies within %.3f m of it",
                  where(goal).c_str(), tolerance);
    return failed(reason);
  }

  eaci::PlanOptions plan_options;
  plan_options.record_pheromone = options.visualize_pheromone;
  if (options.max_planning_time > 0) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.max_planning_time);
    plan_options.should_stop = [deadline](int) { return std::chrono::steady_clock::now() >= deadline; };
  }
  GridPlan plan;
  plan.result = eaci::plan(view, *start_cell, *reachable_goal, options.algorithm, params, plan_options);
  if (!plan.result.success()) {
    plan.error = plan.result.interrupted ? "no route found within max_planning_time" : plan.result.error;
    return plan;
  }
  geometry_msgs::PoseStamped target = goal;
  if (!(*reachable_goal == *goal_cell)) cellCentre(frame, *reachable_goal, target.pose.position.x, target.pose.position.y);
  plan.path = toPath(plan.result.path, frame, start, target, ros::Time::now());
  plan.ok = true;
  return plan;
}

}  // namespace eaci_ros
