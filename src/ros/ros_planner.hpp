// The ROS half the move_base plugin and the planner node share, around the ROS-free planning
// service (src/service/planning_service.hpp): the parameters and dynamic_reconfigure, the ~plan
// topic, the debug topics ~grid_plan, ~islands and ~pheromone (made only while subscribed), the ~make_plan, ~cancel and ~save_costmap services, poses in and a
// nav_msgs/Path out. Nothing here throws into its host: every entry point catches.
#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/GetPlan.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "grid_conversion.hpp"
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

  // The plugins: calls `plan` with the costmap itself (its cells, not a copy) and what changed
  // in it since the last call, under the costmap's own lock, held until `plan` returns (move_base
  // already holds it around makePlan; it is recursive). Throws std::runtime_error with the
  // reason when there is no costmap.
  using CostmapPlan = std::function<PlanReply(const CostmapView& costmap, const CostmapChanges& changes)>;
  using CostmapBorrow = std::function<PlanReply(const CostmapPlan& plan)>;

  struct Setup {
    std::string who;               // starts every log line
    bool latch_plan = false;       // the node latches ~plan
    CostmapSource costmap;         // a copy: the node's plans, and ~make_plan and ~save_costmap
    CostmapBorrow borrow;          // optional: plan() borrows the costmap instead of copying it
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

  // What a plan came to, for an adapter that reports more than yes or no (Move Base Flex).
  struct Answer {
    PlanOutcome outcome = PlanOutcome::kInternalError;
    // A pose was not in the costmap's frame: no plan was tried (outcome kStartOffMap or kGoalOffMap).
    bool wrong_frame = false;
    // kOk: the route's cost as the planner minimised it (result.cost: the sum of its move costs,
    // a straight free step costs 1); 0 otherwise.
    double cost = 0.0;
    std::string message;  // the service's sentence: why it failed, or what was found
  };

  // Plans from `start` to `goal` (poses in the costmap's frame). On failure a log line names the
  // outcome (toName(PlanOutcome)) and the reason, and `plan` is empty. tolerance < 0:
  // default_tolerance. Never throws.
  Answer plan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal, double tolerance,
              std::vector<geometry_msgs::PoseStamped>& plan) noexcept;
  // plan(), as yes or no (the move_base plugin).
  bool makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal, double tolerance,
                std::vector<geometry_msgs::PoseStamped>& plan) noexcept {
    return this->plan(start, goal, tolerance, plan).outcome == PlanOutcome::kOk;
  }

  // Asks the plan in progress to stop (PlanningService::cancel); false when none runs.
  bool cancel() noexcept { return service_ && service_->cancel(); }

  // The options in force (the node inflates its map with them).
  RosPlannerOptions options() const { return config_->options(); }

 private:
  // The reply's route as `plan` (published when asked), or its failure logged with its outcome
  // (`from_service`: for ~make_plan).
  Answer answerFor(const PlanReply& reply, const geometry_msgs::PoseStamped& start,
                   const geometry_msgs::PoseStamped& goal, std::vector<geometry_msgs::PoseStamped>& plan,
                   bool from_service, std::chrono::steady_clock::time_point entered);
  PlanRequest requestFor(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                         double tolerance) const;
  Answer failedWith(const char* what, std::vector<geometry_msgs::PoseStamped>& plan) noexcept;
  // ~grid_plan and ~islands of `reply`, each only while it has a subscriber.
  void publishDebug(const PlanReply& reply, const TfMapFrame& frame, const geometry_msgs::PoseStamped& start,
                    const geometry_msgs::PoseStamped& goal);
  bool onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response);
  bool onCancel(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  bool onSaveCostmap(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);

  Setup setup_;
  std::unique_ptr<PlanningService> service_;
  std::unique_ptr<PlannerConfiguration> config_;
  ros::Publisher plan_pub_;
  ros::Publisher pheromone_pub_;
  ros::Publisher grid_plan_pub_;  // ~grid_plan: the route before smoothing, made only while someone listens
  ros::Publisher islands_pub_;    // ~islands: EACI's islands as markers, the same
  ros::ServiceServer make_plan_service_;
  ros::ServiceServer save_costmap_service_;
  ros::CallbackQueue cancel_queue_;
  std::unique_ptr<ros::AsyncSpinner> cancel_spinner_;
  ros::ServiceServer cancel_service_;
};

}  // namespace eaci_ros
