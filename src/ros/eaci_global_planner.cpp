#include "eaci_global_planner.hpp"

#include <costmap_2d/cost_values.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <pluginlib/class_list_macros.hpp>

#include <mutex>

#include "grid_conversion.hpp"
#include "grid_planner.hpp"

PLUGINLIB_EXPORT_CLASS(eaci_ros::EaciGlobalPlanner, nav_core::BaseGlobalPlanner)

namespace eaci_ros {

EaciGlobalPlanner::EaciGlobalPlanner(std::string name, costmap_2d::Costmap2DROS* costmap_ros) {
  initialize(std::move(name), costmap_ros);
}

void EaciGlobalPlanner::initialize(std::string name, costmap_2d::Costmap2DROS* costmap_ros) {
  if (initialized_) {
    ROS_WARN("EaciGlobalPlanner %s: already initialised", name.c_str());
    return;
  }
  name_ = name;
  costmap_ros_ = costmap_ros;
  ros::NodeHandle private_nh("~/" + name);
  config_ = std::make_unique<PlannerConfiguration>(private_nh, plan_mutex_, "EaciGlobalPlanner " + name);
  plan_pub_ = private_nh.advertise<nav_msgs::Path>("plan", 1);
  pheromone_pub_ = private_nh.advertise<nav_msgs::OccupancyGrid>("pheromone", 1, true);
  make_plan_service_ = private_nh.advertiseService("make_plan", &EaciGlobalPlanner::onMakePlan, this);
  ros::NodeHandle cancel_nh("~/" + name);
  cancel_nh.setCallbackQueue(&cancel_queue_);
  cancel_service_ = cancel_nh.advertiseService("cancel", &EaciGlobalPlanner::onCancel, this);
  cancel_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &cancel_queue_);
  cancel_spinner_->start();
  initialized_ = true;
  std::lock_guard<std::mutex> lock(plan_mutex_);
  const eaci::Parameters& params = config_->params();
  ROS_INFO("EaciGlobalPlanner %s: %s, %d ants x %d iterations, N = %d, %s islands, max_planning_time %.2f s%s",
           name.c_str(), eaci::toString(config_->options().algorithm), params.ants, params.max_iterations,
           params.islands, eaci::toString(params.island_strategy), config_->options().max_planning_time,
           config_->error().empty() ? "" : " (but a parameter is bad: no plans until it is fixed)");
}

bool EaciGlobalPlanner::makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                                 std::vector<geometry_msgs::PoseStamped>& plan) {
  return planWithTolerance(start, goal, -1.0, plan);
}

bool EaciGlobalPlanner::planWithTolerance(const geometry_msgs::PoseStamped& start,
                                          const geometry_msgs::PoseStamped& goal, double tolerance,
                                          std::vector<geometry_msgs::PoseStamped>& plan) {
  plan.clear();
  if (!initialized_) {
    ROS_ERROR("EaciGlobalPlanner: makePlan called before initialize()");
    return false;
  }
  const std::string frame = costmap_ros_->getGlobalFrameID();
  for (const auto* pose : {&start, &goal}) {
    if (pose->header.frame_id != frame) {
      ROS_ERROR("EaciGlobalPlanner %s: the %s is in frame '%s', the costmap in '%s'", name_.c_str(),
                pose == &start ? "start" : "goal", pose->header.frame_id.c_str(), frame.c_str());
      return false;
    }
  }

  std::lock_guard<std::mutex> one_at_a_time(plan_mutex_);
  if (!config_->error().empty()) {
    ROS_ERROR("EaciGlobalPlanner %s: %s: refusing to plan until it is fixed", name_.c_str(), config_->error().c_str());
    return false;
  }
  const eaci::Parameters& params = config_->params();
  const RosPlannerOptions& options = config_->options();
  if (tolerance < 0) tolerance = options.default_tolerance;
  const PlanCancellation::Scope in_progress(cancellation_);
  costmap_2d::Costmap2D* costmap = costmap_ros_->getCostmap();
  GridPlan result;
  MapFrame map_frame;
  {
    std::unique_lock<costmap_2d::Costmap2D::mutex_t> lock(*costmap->getMutex());
    map_frame.frame_id = frame;
    map_frame.origin = {costmap->getOriginX(), costmap->getOriginY()};
    map_frame.resolution = costmap->getResolution();
    map_frame.width = static_cast<int>(costmap->getSizeInCellsX());
    map_frame.height = static_cast<int>(costmap->getSizeInCellsY());
    // The costmap's own costs (the inflation gradient) weigh every move (the cost model).
    eaci::CellInterpretation costs =
        eaci::CellInterpretation::costmap(static_cast<std::uint8_t>(params.lethal_cost), params.allow_unknown);
    costs.unknown_value = costmap_2d::NO_INFORMATION;
    const eaci::GridView view(costmap->getCharMap(), map_frame.width, map_frame.height, eaci::RowOrder::kBottomFirst,
                              costs);
    result = planOnGrid(view, map_frame, start, goal, tolerance, params, options, cancellation_.flag());
  }
  if (!result.ok) {
    ROS_WARN("EaciGlobalPlanner %s: %s", name_.c_str(), result.error.c_str());
    return false;
  }
  if (result.stopped_by != StopReason::kNone)
    ROS_INFO("EaciGlobalPlanner %s: %s after %d iterations: returning the best route so far", name_.c_str(),
             toString(result.stopped_by), result.result.iterations_run);
  plan = result.path.poses;
  if (options.publish_plan) plan_pub_.publish(result.path);
  if (options.visualize_pheromone && !result.result.pheromone.empty())
    pheromone_pub_.publish(fieldToGrid(result.result.pheromone, map_frame, ros::Time::now()));
  return true;
}

bool EaciGlobalPlanner::onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response) {
  const std::string frame = costmap_ros_ ? costmap_ros_->getGlobalFrameID() : std::string();
  geometry_msgs::PoseStamped start = request.start, goal = request.goal;
  if (start.header.frame_id.empty()) start.header.frame_id = frame;
  if (goal.header.frame_id.empty()) goal.header.frame_id = frame;
  // The request's own tolerance when > 0, else default_tolerance.
  planWithTolerance(start, goal, request.tolerance > 0 ? request.tolerance : -1.0, response.plan.poses);
  response.plan.header.frame_id = frame;
  response.plan.header.stamp = ros::Time::now();
  return true;
}

bool EaciGlobalPlanner::onCancel(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  response.success = cancellation_.cancel();
  response.message = response.success
                         ? "cancelling the plan in progress: it stops at its next iteration with the best route so far"
                         : "no plan in progress";
  ROS_INFO("EaciGlobalPlanner %s: cancel: %s", name_.c_str(), response.message.c_str());
  return true;
}

}  // namespace eaci_ros
