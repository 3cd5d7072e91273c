// eaci_planner/EaciCostmapPlanner: EACI as a Move Base Flex mbf_costmap_core::CostmapPlanner. The
// same thin adapter as the move_base plugin (eaci_global_planner.hpp): it copies the costmap's
// cells under the costmap's lock, lets go of it, and hands the copy to the planning service
// through RosPlanner; the outcome goes back as mbf_msgs/GetPath's code (mbf_outcome.hpp), with
// the route's cost and the service's sentence, and cancel() stops the plan in progress.
#pragma once

#include <costmap_2d/costmap_2d_ros.h>
#include <geometry_msgs/PoseStamped.h>
#include <mbf_costmap_core/costmap_planner.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ros_planner.hpp"

namespace eaci_ros {

class EaciCostmapPlanner : public mbf_costmap_core::CostmapPlanner {
 public:
  EaciCostmapPlanner() = default;

  // Parameters, topics and services under ~<name>/ (docs/ros.md), as the move_base plugin's.
  void initialize(std::string name, costmap_2d::Costmap2DROS* costmap_ros) override;

  // An mbf_msgs::GetPathResult code (mbf_outcome.hpp); `cost` the route's cost, `message` the
  // service's sentence. Never throws, never outlasts max_planning_time.
  uint32_t makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal, double tolerance,
                    std::vector<geometry_msgs::PoseStamped>& plan, double& cost, std::string& message) override;

  // Stops the plan in progress (it returns CANCELED, or its best route so far); true once
  // initialised: a cancel that comes before the plan starts is Move Base Flex's to keep.
  bool cancel() override;

 private:
  std::unique_ptr<RosPlanner> planner_;
};

}  // namespace eaci_ros
