// The ROS half the move_base plugin and the planner node share, around the ROS-free planning
// service (src/service/planning_service.hpp): the parameters and dynamic_reconfigure, the ~plan
// and ~pheromone topics, the ~make_plan, ~cancel and ~save_costmap services, poses in and a
// nav_msgs/Path out. Nothing here throws into its host: every entry point catches.
#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/GetPlan.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "planner_configuration.hpp"
#include "planning_service.hpp"

namespace eaci_ros {

class RosPlanner {
 public:
  // A copy of the costmap the next plan runs on, taken under the costmap's own lock and
  // released before it returns (so no lock of ours is ever waited for while it is held).
  // Throws std::runtime_error with the reason when there is none (no map yet).
  using CostmapSource = std::function<CostmapSnapshot()>;
  // Puts a ~make_plan request's pose into `frame` (the node: TF), or false with the reason.
  // Without one, a pose must be in the costmap's frame (an empty frame id means that frame).
  using PoseTransform =
      std::function<bool(const geometry_msgs::PoseStamped& pose, const std::string& frame,
                         geometry_msgs::PoseStamped& out, std::string& error)>;

  struct Setup {
    std::string who;               // starts every log line
    bool latch_plan = false;       // the node latches ~plan
    CostmapSource costmap;
    PoseTransform transform;       // optional
    // The costmaps are costmap_2d's (the plugin): plan on one it has emptied (resized or cleared,
    // not yet updated) as the last filled one showed it (ServiceSettings).
    bool from_costmap_2d = false;
  };

  // Reads the parameters under `private_nh` (plus ~save_costmap_dir, ~save_costmap_on_failure,
  // ~save_costmap_keep), serves dynamic_reconfigure, advertises the topics and services there.
  // ~cancel has a callback queue and a thread of its own, so it is answered while the host's
  // threads plan.
  RosPlanner(const ros::NodeHandle& private_nh, Setup setup);
  ~RosPlanner();

  // Plans from `start` to `goal` (poses in the costmap's frame). false with a log line naming
  // the outcome (toName(PlanOutcome)) and the reason; `plan` empty then. tolerance < 0:
  // default_tolerance. Never throws.
  bool makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal, double tolerance,
                std::vector<geometry_msgs::PoseStamped>& plan) noexcept;

  // The options in force (the node inflates its map with them).
  RosPlannerOptions options() const { return config_->options(); }

 private:
  // Plans on `costmap` (poses already in its frame), publishes; false when the service said no
  // (logged with the outcome; `from_service`: for ~make_plan).
  bool planOn(CostmapSnapshot costmap, const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
              double tolerance, std::vector<geometry_msgs::PoseStamped>& plan, bool from_service);
  void failedWith(const char* what, std::vector<geometry_msgs::PoseStamped>& plan) noexcept;
  bool onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response);
  bool onCancel(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  bool onSaveCostmap(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);

  Setup setup_;
  std::unique_ptr<PlanningService> service_;
  std::unique_ptr<PlannerConfiguration> config_;
  ros::Publisher plan_pub_;
  ros::Publisher pheromone_pub_;
  ros::ServiceServer make_plan_service_;
  ros::ServiceServer save_costmap_service_;
  ros::CallbackQueue cancel_queue_;
  std::unique_ptr<ros::AsyncSpinner> cancel_spinner_;
  ros::ServiceServer cancel_service_;
};

}  // namespace eaci_ros
