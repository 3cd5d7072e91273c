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
#include <optional>
#include <string>
#include <vector>

#include "costmap_replay.hpp"
#include "eaci/aco/parameters.hpp"
#include "eaci/search/grid_search.hpp"
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
  // spinner threads plan. ~<name>/save_costmap (std_srvs/Trigger) saves the costmap for replay
  // with eaci_plan (see onSaveCostmap), as a failed plan does with ~save_costmap_on_failure.
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
  // ~<name>/save_costmap (std_srvs/Trigger): the current costmap (copied under its mutex) as a
  // raw map in ~save_costmap_dir, with the last request and the eaci_plan command replaying it.
  bool onSaveCostmap(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  // Writes the files (costmap_replay.hpp) and logs their paths; "" or the reason it failed.
  std::string saveForReplay(const std::string& prefix, const CostmapSnapshot& costmap,
                            const std::optional<PlanRecord>& request, const std::string& note,
                            const eaci::Parameters& params, const RosPlannerOptions& options, ReplayFiles& files);

  bool initialized_ = false;
  std::string name_;
  costmap_2d::Costmap2DROS* costmap_ros_ = nullptr;
  std::unique_ptr<PlannerConfiguration> config_;  // read and changed under plan_mutex_
  ros::Publisher plan_pub_;
  ros::Publisher pheromone_pub_;
  ros::ServiceServer make_plan_service_;
  std::mutex plan_mutex_;
  PlanCancellation cancellation_;
  eaci::PlannerWorkspace workspace_;  // the planner's buffers and threads, kept between plans (under plan_mutex_)
  ros::CallbackQueue cancel_queue_;
  std::unique_ptr<ros::AsyncSpinner> cancel_spinner_;
  ros::ServiceServer cancel_service_;
  // Saving costmaps for offline replay: ~save_costmap_dir (default /tmp), and
  // ~save_costmap_on_failure (default false) to save the costmap of every failed plan.
  std::string save_costmap_dir_ = "/tmp";
  bool save_costmap_on_failure_ = false;
  ros::ServiceServer save_costmap_service_;
  std::mutex last_plan_mutex_;
  std::optional<PlanRecord> last_plan_;  // the last request that reached the costmap, and its outcome
};

}  // namespace eaci_ros
