// eaci_planner/EaciGlobalPlanner: EACI as a nav_core::BaseGlobalPlanner for move_base.
// A thin adapter: it views the costmap's char map through the core's grid view (no copy of
// the costmap, under its mutex) and hands the request to planOnGrid().
#pragma once

#include <costmap_2d/costmap_2d_ros.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_core/base_global_planner.h>
#include <nav_msgs/GetPlan.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "eaci/aco/parameters.hpp"
#include "plan_cancellation.hpp"
#include "planner_configuration.hpp"

namespace eaci_ros {

class EaciGlobalPlanner : public nav_core::BaseGlobalPlanner {
 public:
  EaciGlobalPlanner() = default;
  EaciGlobalPlanner(std::string name, costmap_2d::Costmap2DROS* costmap_ros);

  // Reads the parameters under ~<name>/ (see ros_parameters.hpp) and serves them there with
  // dynamic_reconfigure (planner_configuration.hpp), advertises ~<name>/plan,
  // ~<name>/pheromone and the ~<name>/make_plan and ~<name>/cancel services. ~cancel
  // (std_srvs/Trigger) stops the plan in progress at its next iteration with the best route so
  // far; it has a callback queue and a thread of its own, so it is answered while the host's
  // spinner threads plan.
  void initialize(std::string name, costmap_2d::Costmap2DROS* costmap_ros) override;

  // false with a ROS_ERROR / ROS_WARN naming the reason: not initialised, a bad parameter (the
  // sentence naming it, on every call until it is fixed), a pose in another frame, start or goal off the costmap, in an obstacle (the goal beyond default_tolerance),
  // or no route (within max_planning_time, before ~cancel or before ROS shut down). Plans run one
  // at a time (move_base's planner thread and the ~make_plan service may ask together).
  bool makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                std::vector<geometry_msgs::PoseStamped>& plan) override;

 private:
  // tolerance < 0: the default_tolerance parameter.
  bool planWithTolerance(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                         double tolerance, std::vector<geometry_msgs::PoseStamped>& plan);
  bool onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response);
  bool onCancel(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);

  bool initialized_ = false;
  std::string name_;
  costmap_2d::Costmap2DROS* costmap_ros_ = nullptr;
  std::unique_ptr<PlannerConfiguration> config_;  // read and changed under plan_mutex_
  ros::Publisher plan_pub_;
  ros::Publisher pheromone_pub_;
  ros::ServiceServer make_plan_service_;
  std::mutex plan_mutex_;
  PlanCancellation cancellation_;
  ros::CallbackQueue cancel_queue_;
  std::unique_ptr<ros::AsyncSpinner> cancel_spinner_;
  ros::ServiceServer cancel_service_;
};

}  // namespace eaci_ros
