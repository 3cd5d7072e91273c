#include "eaci_global_planner.hpp"

#include <pluginlib/class_list_macros.hpp>

#include "costmap_2d_copy.hpp"

PLUGINLIB_EXPORT_CLASS(eaci_ros::EaciGlobalPlanner, nav_core::BaseGlobalPlanner)

namespace eaci_ros {

EaciGlobalPlanner::EaciGlobalPlanner(std::string name, costmap_2d::Costmap2DROS* costmap_ros) {
  initialize(std::move(name), costmap_ros);
}

void EaciGlobalPlanner::initialize(std::string name, costmap_2d::Costmap2DROS* costmap_ros) {
  if (planner_) {
    ROS_WARN("EaciGlobalPlanner %s: already initialised", name.c_str());
    return;
  }
  try {
    costmap_ros_ = costmap_ros;
    planner_ = std::make_unique<RosPlanner>(ros::NodeHandle("~/" + name),
                                            RosPlanner::Setup{"EaciGlobalPlanner " + name, false,
                                                              [this] { return copyCostmap(); }, {}, true});
  } catch (const std::exception& e) {
    planner_.reset();
    ROS_ERROR("EaciGlobalPlanner %s: cannot start: %s (every plan will fail)", name.c_str(), e.what());
  } catch (...) {  // move_base must not see an exception from a plugin's initialize (docs/ros.md: "everything")
    planner_.reset();
    ROS_ERROR("EaciGlobalPlanner %s: cannot start: an unknown exception (every plan will fail)", name.c_str());
  }
}

CostmapSnapshot EaciGlobalPlanner::copyCostmap() const { return copyCostmap2D(costmap_ros_); }

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
