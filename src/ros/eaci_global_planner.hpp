// eaci_planner/EaciGlobalPlanner: EACI as a nav_core::BaseGlobalPlanner for move_base. A thin
// adapter: it copies the costmap's cells under the costmap's lock, lets go of it, and hands
// the copy to the planning service (ros_planner.hpp, src/service/planning_service.hpp), which
// owns everything else and is tested in CI without the navigation stack.
#pragma once

#include <costmap_2d/costmap_2d_ros.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_core/base_global_planner.h>

#include <memory>
#include <string>
#include <vector>

#include "ros_planner.hpp"

namespace eaci_ros {

class EaciGlobalPlanner : public nav_core::BaseGlobalPlanner {
 public:
  EaciGlobalPlanner() = default;
  EaciGlobalPlanner(std::string name, costmap_2d::Costmap2DROS* costmap_ros);

  // Parameters, topics and services under ~<name>/ (docs/ros.md): ~plan, ~pheromone,
  // ~make_plan, ~cancel, ~save_costmap; dynamic_reconfigure.
  void initialize(std::string name, costmap_2d::Costmap2DROS* costmap_ros) override;

  // false with a log line naming the reason; never throws, never outlasts max_planning_time.
  bool makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                std::vector<geometry_msgs::PoseStamped>& plan) override;

 private:
  std::unique_ptr<RosPlanner> planner_;
};

}  // namespace eaci_ros
