#include "eaci_global_planner.hpp"

#include <costmap_2d/cost_values.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <pluginlib/class_list_macros.hpp>

#include <mutex>

#include "eaci/io/text.hpp"
#include "grid_conversion.hpp"
#include "grid_planner.hpp"

PLUGINLIB_EXPORT_CLASS(eaci_ros::EaciGlobalPlanner, nav_core::BaseGlobalPlanner)

namespace eaci_ros {
namespace {

// A copy of the costmap's char map and frame; the caller holds the costmap's mutex.
CostmapSnapshot snapshotOf(costmap_2d::Costmap2D& costmap, const MapFrame& frame) {
  CostmapSnapshot snapshot;
  snapshot.frame = frame;
  const unsigned char* cells = costmap.getCharMap();
  snapshot.cells.assign(cells, cells + static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height));
  return snapshot;
}

MapFrame costmapFrame(costmap_2d::Costmap2D& costmap, const std::string& frame_id) {
  MapFrame frame;
  frame.frame_id = frame_id;
  frame.origin = {costmap.getOriginX(), costmap.getOriginY()};
  frame.resolution = costmap.getResolution();
  frame.width = static_cast<int>(costmap.getSizeInCellsX());
  frame.height = static_cast<int>(costmap.getSizeInCellsY());
  return frame;
}

}  // namespace

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
  private_nh.param("save_costmap_dir", save_costmap_dir_, std::string("/tmp"));
  private_nh.param("save_costmap_on_failure", save_costmap_on_failure_, false);
  save_costmap_service_ = private_nh.advertiseService("save_costmap", &EaciGlobalPlanner::onSaveCostmap, this);
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
  // Copy the costmap (one memcpy of its char map) and let go of its mutex before planning, so
  // the costmap's update loop is not held up by the search. move_base's own planning thread
  // holds that mutex around the whole makePlan anyway (MoveBase::makePlan); the copy frees it
  // for the ~make_plan services and for a costmap that changes size during a plan.
  CostmapSnapshot snapshot;
  {
    costmap_2d::Costmap2D* costmap = costmap_ros_->getCostmap();
    std::unique_lock<costmap_2d::Costmap2D::mutex_t> lock(*costmap->getMutex());
    snapshot = snapshotOf(*costmap, costmapFrame(*costmap, frame));
  }
  const MapFrame& map_frame = snapshot.frame;
  // The costmap's own costs (the inflation gradient) weigh every move (the cost model).
  eaci::CellInterpretation costs =
      eaci::CellInterpretation::costmap(static_cast<std::uint8_t>(params.lethal_cost), params.allow_unknown);
  costs.unknown_value = costmap_2d::NO_INFORMATION;
  const eaci::GridView view(snapshot.cells.data(), map_frame.width, map_frame.height, eaci::RowOrder::kBottomFirst,
                            costs);
  // The pheromone picture costs a pass over the whole map and a map-sized message: made only
  // while someone listens (as navfn's potential is only made when asked for).
  RosPlannerOptions plan_options = options;
  plan_options.visualize_pheromone = options.visualize_pheromone && pheromone_pub_.getNumSubscribers() > 0;
  const GridPlan result = planOnGrid(view, map_frame, start, goal, tolerance, params, plan_options,
                                     cancellation_.flag(), &workspace_);
  PlanRecord record;
  record.start = {start.pose.position.x, start.pose.position.y};
  record.goal = {goal.pose.position.x, goal.pose.position.y};
  record.tolerance = tolerance;
  record.outcome = describeOutcome(result.ok, result.error, result.result, map_frame.resolution);
  {
    std::lock_guard<std::mutex> lock(last_plan_mutex_);
    last_plan_ = record;
  }
  if (!result.ok) {
    ROS_WARN("EaciGlobalPlanner %s: %s", name_.c_str(), result.error.c_str());
    ReplayFiles files;
    if (save_costmap_on_failure_) saveForReplay("eaci_failed_plan", snapshot, record, "the costmap of a failed plan", params, options, files);
    return false;
  }
  if (result.stopped_by != StopReason::kNone)
    ROS_INFO("EaciGlobalPlanner %s: %s after %d iterations: returning %s", name_.c_str(),
             toString(result.stopped_by), result.result.iterations_run,
             result.result.route_from_search ? "the cheapest route the islands sit on (no ant had arrived yet)"
                                             : "the best route so far");
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

bool EaciGlobalPlanner::onSaveCostmap(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  if (!initialized_) {
    response.success = false;
    response.message = "not initialised";
    return true;
  }
  CostmapSnapshot snapshot;
  {
    costmap_2d::Costmap2D* costmap = costmap_ros_->getCostmap();
    std::unique_lock<costmap_2d::Costmap2D::mutex_t> lock(*costmap->getMutex());
    snapshot = snapshotOf(*costmap, costmapFrame(*costmap, costmap_ros_->getGlobalFrameID()));
  }
  std::optional<PlanRecord> last;
  {
    std::lock_guard<std::mutex> lock(last_plan_mutex_);
    last = last_plan_;
  }
  eaci::Parameters params;
  RosPlannerOptions options;
  {
    std::lock_guard<std::mutex> lock(plan_mutex_);  // waits for a plan in progress
    params = config_->params();
    options = config_->options();
  }
  ReplayFiles files;
  const std::string error = saveForReplay(
      "eaci_costmap", snapshot, last,
      last ? "the costmap when ~save_costmap was called; the request below is the last one planned"
           : "the costmap when ~save_costmap was called; no plan had been asked for",
      params, options, files);
  response.success = error.empty();
  response.message = error.empty() ? files.map_yaml + (files.command.empty() ? "" : "; replay: " + files.command) : error;
  return true;
}

std::string EaciGlobalPlanner::saveForReplay(const std::string& prefix, const CostmapSnapshot& costmap,
                                             const std::optional<PlanRecord>& request, const std::string& note,
                                             const eaci::Parameters& params, const RosPlannerOptions& options,
                                             ReplayFiles& files) {
  const std::vector<std::string> notes = {
      "saved by the move_base plugin EaciGlobalPlanner " + name_ + ": " + note,
      "costmap_2d costs: 0 free, 1..252 cost, 253/254 obstacles, 255 unknown (lethal_cost " +
          std::to_string(params.lethal_cost) + ", allow_unknown " + (params.allow_unknown ? "true" : "false") + ")",
      "the plugin's max_planning_time was " + eaci::formatNumber(options.max_planning_time) +
          " s; the replay runs every iteration"};
  try {
    files = saveCostmapForReplay(save_costmap_dir_, timestampedName(prefix), costmap, params, options.algorithm,
                                 request, notes);
  } catch (const std::exception& e) {
    ROS_ERROR("EaciGlobalPlanner %s: cannot save the costmap: %s", name_.c_str(), e.what());
    return e.what();
  }
  ROS_INFO("EaciGlobalPlanner %s: saved the costmap as %s (+ %s, parameters %s)", name_.c_str(),
           files.map_yaml.c_str(), files.map_image.c_str(), files.params_yaml.c_str());
  if (!files.command.empty()) ROS_INFO("EaciGlobalPlanner %s: replay with: %s", name_.c_str(), files.command.c_str());
  return "";
}

}  // namespace eaci_ros
