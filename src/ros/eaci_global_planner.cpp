#include "eaci_global_planner.hpp"

#include <pluginlib/class_list_macros.hpp>

#include "costmap_2d_planner.hpp"

PLUGINLIB_EXPORT_CLASS(eaci_ros::EaciGlobalPlanner, nav_core::BaseGlobalPlanner)

namespace eaci_ros {

EaciGlobalPlanner::EaciGlobalPlanner(std::string name, costmap_2d::Costmap2DROS* costmap_ros) {
  initialize(std::move(name), costmap_ros);
}

void EaciGlobalPlanner::initialize(std::string name, costmap_2d::Costmap2DROS* costmap_ros) {
  startCostmap2DPlanner(planner_, "EaciGlobalPlanner", name, costmap_ros);
}

bool EaciGlobalPlanner::makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                                 std::vector<geometry_msgs::PoseStamped>& plan) {
  plan.clear();
  if (!planner_) {
    ROS_ERROR("EaciGlobalPlanner: no plan (%s): makePlan called before a successful initialize()",
              toName(PlanOutcome::kNotInitialised));
    return false;
  }
  return planner_->makePlan(start, goal, -1.0, plan);
}

}  // namespace eaci_ros
