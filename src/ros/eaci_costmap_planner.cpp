#include "eaci_costmap_planner.hpp"

#include <mbf_msgs/GetPathResult.h>
#include <pluginlib/class_list_macros.hpp>

#include "costmap_2d_planner.hpp"
#include "mbf_outcome.hpp"

PLUGINLIB_EXPORT_CLASS(eaci_ros::EaciCostmapPlanner, mbf_costmap_core::CostmapPlanner)

namespace eaci_ros {

void EaciCostmapPlanner::initialize(std::string name, costmap_2d::Costmap2DROS* costmap_ros) {
  startCostmap2DPlanner(planner_, "EaciCostmapPlanner", name, costmap_ros);
}

uint32_t EaciCostmapPlanner::makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                                      double tolerance, std::vector<geometry_msgs::PoseStamped>& plan, double& cost,
                                      std::string& message) {
  plan.clear();
  cost = 0.0;
  try {
    if (!planner_) {
      message = "EaciCostmapPlanner: makePlan called before a successful initialize()";
      ROS_ERROR("%s", message.c_str());
      return mbfOutcome(PlanOutcome::kNotInitialised);
    }
    // GetPath's tolerance 0 (its default) means default_tolerance, as move_base's make_plan.
    RosPlanner::Answer answer = planner_->plan(start, goal, tolerance > 0 ? tolerance : -1.0, plan);
    cost = answer.cost;
    message = std::move(answer.message);
    // Move Base Flex puts both poses into the costmap's frame first: a pose in another is its TF's doing.
    if (answer.wrong_frame) return mbf_msgs::GetPathResult::TF_ERROR;
    return mbfOutcome(answer.outcome);
  } catch (...) {  // nothing above throws but the message's copy
    plan.clear();
    return mbfOutcome(PlanOutcome::kInternalError);
  }
}

bool EaciCostmapPlanner::cancel() {
  if (!planner_) return false;
  const bool stopping = planner_->cancel();
  ROS_INFO("EaciCostmapPlanner: cancel: %s", stopping ? "stopping the plan in progress" : "no plan in progress");
  return true;
}

}  // namespace eaci_ros
