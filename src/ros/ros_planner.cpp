#include "ros_planner.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>

#include <cstdio>
#include <utility>

#include "grid_conversion.hpp"

namespace eaci_ros {
namespace {

void logLine(LogLevel level, const std::string& line) {
  switch (level) {
    case LogLevel::kDebug: ROS_DEBUG("%s", line.c_str()); break;
    case LogLevel::kInfo: ROS_INFO("%s", line.c_str()); break;
    case LogLevel::kWarn: ROS_WARN("%s", line.c_str()); break;
    case LogLevel::kError: ROS_ERROR("%s", line.c_str()); break;
  }
}

// "who: no plan (no_path): goal (...) cannot be reached ...": the outcome's word, then the sentence.
void logFailure(const std::string& who, const char* what, const PlanReply& reply) {
  const bool fault = reply.outcome == PlanOutcome::kBadParameters || reply.outcome == PlanOutcome::kBadCostmap ||
                     reply.outcome == PlanOutcome::kInternalError || reply.outcome == PlanOutcome::kNotInitialised;
  logLine(fault ? LogLevel::kError : LogLevel::kWarn,
          who + ": " + what + "no plan (" + toName(reply.outcome) + "): " + reply.error);
}

TfMapFrame rosFrame(const PlanReply& reply) {
  TfMapFrame frame;
  static_cast<eaci::MapFrame&>(frame) = reply.frame;
  frame.frame_id = reply.frame_id;
  return frame;
}

}  // namespace

RosPlanner::RosPlanner(const ros::NodeHandle& private_nh, Setup setup) : setup_(std::move(setup)) {
  ServiceSettings settings;
  settings.who = setup_.who;
  private_nh.param("save_costmap_dir", settings.save_costmap_dir, std::string("/tmp"));
  private_nh.param("save_costmap_on_failure", settings.save_costmap_on_failure, false);
  private_nh.param("save_costmap_keep", settings.save_costmap_keep, 10);
  settings.shutting_down = [] { return !ros::ok() || ros::isShuttingDown(); };
  // ~stand_in_for_emptied_costmaps: plan on the last filled costmap while costmap_2d refills one it resized.
  settings.stand_in_for_emptied_costmaps =
      setup_.from_costmap_2d && private_nh.param("stand_in_for_emptied_costmaps", true);
  service_ = std::make_unique<PlanningService>(std::move(settings), &logLine);
  config_ = std::make_unique<PlannerConfiguration>(
      private_nh, setup_.who,
      [this](const eaci::Parameters& params, const RosPlannerOptions& options, const std::string& error) {
        service_->configure(params, options, error);
      });
  ros::NodeHandle nh(private_nh);
  plan_pub_ = nh.advertise<nav_msgs::Path>("plan", 1, setup_.latch_plan);
  pheromone_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("pheromone", 1, true);
  grid_plan_pub_ = nh.advertise<nav_msgs::Path>("grid_plan", 1, setup_.latch_plan);
  islands_pub_ = nh.advertise<visualization_msgs::MarkerArray>("islands", 1, setup_.latch_plan);
  make_plan_service_ = nh.advertiseService("make_plan", &RosPlanner::onMakePlan, this);
  save_costmap_service_ = nh.advertiseService("save_costmap", &RosPlanner::onSaveCostmap, this);
  ros::NodeHandle cancel_nh(private_nh);
  cancel_nh.setCallbackQueue(&cancel_queue_);
  cancel_service_ = cancel_nh.advertiseService("cancel", &RosPlanner::onCancel, this);
  cancel_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &cancel_queue_);
  cancel_spinner_->start();
  const PlanningService::Configuration config = service_->configuration();
  ROS_INFO("%s: %s, %d ants x %d iterations, N = %d, %s islands, max_planning_time %.2f s%s", setup_.who.c_str(),
           eaci::toString(config.options.algorithm), config.params.ants, config.params.max_iterations,
           config.params.islands, eaci::toString(config.params.island_strategy), config.options.max_planning_time,
           config.error.empty() ? "" : " (but a parameter is bad: no plans until it is fixed)");
}

RosPlanner::~RosPlanner() {
  if (cancel_spinner_) cancel_spinner_->stop();
  if (service_) service_->cancel();
}

namespace {

// The answer for a pose not in the costmap's frame (no plan tried), or none.
std::optional<RosPlanner::Answer> frameRefusal(const std::string& who, const geometry_msgs::PoseStamped& start,
                                               const geometry_msgs::PoseStamped& goal, const std::string& frame_id) {
  for (const auto* pose : {&start, &goal}) {
    if (pose->header.frame_id == frame_id) continue;
    RosPlanner::Answer answer;
    answer.outcome = pose == &start ? PlanOutcome::kStartOffMap : PlanOutcome::kGoalOffMap;
    answer.wrong_frame = true;
    answer.message = std::string("the ") + (pose == &start ? "start" : "goal") + " is in frame '" +
                     pose->header.frame_id + "', the costmap in '" + frame_id + "'";
    ROS_ERROR("%s: no plan (%s): %s", who.c_str(), toName(answer.outcome), answer.message.c_str());
    return answer;
  }
  return std::nullopt;
}

double msSince(std::chrono::steady_clock::time_point from) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - from).count();
}

// How long each step of a plan took, at DEBUG on the logger ros.eaci_planner.profile: the
// service's phases, then the conversion to nav_msgs/Path and publishing, then the whole call
// from `entered` (the costmap's lock and the copy or borrowing included).
void logProfile(const std::string& who, const PlanReply& reply, double convert_ms, double publish_ms,
                std::chrono::steady_clock::time_point entered) {
  ROS_DEBUG_NAMED("profile", "%s: %s, to nav_msgs/Path %.3f, publishing %.3f; the call %.3f ms", who.c_str(),
                  describePhases(reply.phases).c_str(), convert_ms, publish_ms, msSince(entered));
}

// The yaw of a pose's orientation, or NaN when the quaternion is not a rotation (all zeros, as
// some tools send a position alone, or not finite): such a pose has no heading to price.
double yawOf(const geometry_msgs::Quaternion& q) {
  const double norm2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (!std::isfinite(norm2) || norm2 < 1e-6) return std::numeric_limits<double>::quiet_NaN();
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), q.w * q.w + q.x * q.x - q.y * q.y - q.z * q.z);  // any scale
}

}  // namespace

PlanRequest RosPlanner::requestFor(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                                   double tolerance) const {
  PlanRequest request;
  request.start = {start.pose.position.x, start.pose.position.y};
  request.goal = {goal.pose.position.x, goal.pose.position.y};
  request.tolerance = tolerance;
  request.start_yaw = yawOf(start.pose.orientation);
  request.goal_yaw = yawOf(goal.pose.orientation);
  request.record_pheromone = pheromone_pub_.getNumSubscribers() > 0;
  return request;
}

RosPlanner::Answer RosPlanner::plan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                                    double tolerance, std::vector<geometry_msgs::PoseStamped>& plan) noexcept {
  const auto entered = std::chrono::steady_clock::now();
  plan.clear();
  try {
    PlanRequest request = requestFor(start, goal, tolerance);
    request.called_at = entered;  // max_planning_time bounds the whole call, the costmap's lock and copy included
    std::optional<Answer> refused;
    PlanReply reply;
    try {
      if (setup_.borrow) {
        reply = setup_.borrow([&](const CostmapView& costmap, const CostmapChanges& changes) {
          refused = frameRefusal(setup_.who, start, goal, costmap.frame_id);
          if (refused) service_->changesNotRead();  // taken from the tracker, not read: read them next time
          return refused ? PlanReply{} : service_->plan(costmap, request, changes);
        });
      } else {
        const CostmapSnapshot costmap = setup_.costmap();
        refused = frameRefusal(setup_.who, start, goal, costmap.frame_id);
        if (!refused) reply = service_->plan(costmap, request);
      }
    } catch (const std::runtime_error& e) {  // no costmap (the service itself never throws)
      Answer answer;
      answer.outcome = PlanOutcome::kBadCostmap;
      answer.message = e.what();
      ROS_ERROR("%s: no plan (%s): %s", setup_.who.c_str(), toName(answer.outcome), e.what());
      return answer;
    }
    if (refused) return *refused;
    return answerFor(reply, start, goal, plan, false, entered);
  } catch (const std::exception& e) {
    return failedWith(e.what(), plan);
  } catch (...) {
    return failedWith("an unknown exception", plan);
  }
}

RosPlanner::Answer RosPlanner::answerFor(const PlanReply& reply, const geometry_msgs::PoseStamped& start,
                                         const geometry_msgs::PoseStamped& goal,
                                         std::vector<geometry_msgs::PoseStamped>& plan, bool from_service,
                                         std::chrono::steady_clock::time_point entered) {
  Answer answer;
  answer.outcome = reply.outcome;
  if (!reply.ok()) {
    logFailure(setup_.who, from_service ? "make_plan: " : "", reply);
    answer.message = reply.error;
    logProfile(setup_.who, reply, 0.0, 0.0, entered);
    return answer;
  }
  const auto convert_start = std::chrono::steady_clock::now();
  geometry_msgs::PoseStamped target = goal;
  target.pose.position.x = reply.goal.x();
  target.pose.position.y = reply.goal.y();
  const TfMapFrame frame = rosFrame(reply);
  const nav_msgs::Path path =
      toPath(reply.poses, frame.frame_id, start, target, ros::Time::now(), reply.options.orientation_mode);
  plan = path.poses;
  const double convert_ms = msSince(convert_start);
  const auto publish_start = std::chrono::steady_clock::now();
  if (reply.options.publish_plan) plan_pub_.publish(path);
  if (!reply.result.pheromone.empty()) pheromone_pub_.publish(fieldToGrid(reply.result.pheromone, frame, ros::Time::now()));
  publishDebug(reply, frame, start, target);
  logProfile(setup_.who, reply, convert_ms, msSince(publish_start), entered);
  answer.cost = reply.result.cost;
  char line[256];
  std::snprintf(line, sizeof(line), "a route of %.2f m (%zu poses, cost %.1f) after %d iterations%s%s%s%s",
                reply.result.smoothed_length * reply.frame.resolution, plan.size(), reply.result.cost,
                reply.result.iterations_run, reply.stopped_by == StopReason::kNone ? "" : ", the best so far: ",
                reply.stopped_by == StopReason::kNone ? "" : toString(reply.stopped_by),
                reply.sent_grid_route ? "; the grid route (the smoothed one failed the check)" : "",
                reply.stood_in_for_emptied ? "; on the last filled costmap (this one was resized and is empty)" : "");
  answer.message = line;
  return answer;
}

void RosPlanner::publishDebug(const PlanReply& reply, const TfMapFrame& frame, const geometry_msgs::PoseStamped& start,
                              const geometry_msgs::PoseStamped& goal) {
  const ros::Time now = ros::Time::now();
  if (grid_plan_pub_.getNumSubscribers() > 0) {  // the 8-connected route, cell centre by cell centre
    std::vector<Eigen::Vector2d> centres;
    centres.reserve(reply.result.path.size());
    for (const eaci::Cell& c : reply.result.path) centres.push_back(frame.cellToWorld(c));
    grid_plan_pub_.publish(toPath(centres, frame.frame_id, start, goal, now, eaci::OrientationMode::kForward));
  }
  if (islands_pub_.getNumSubscribers() > 0) islands_pub_.publish(islandMarkers(reply.result.islands, frame, now));
}

RosPlanner::Answer RosPlanner::failedWith(const char* what, std::vector<geometry_msgs::PoseStamped>& plan) noexcept {
  plan.clear();
  Answer answer;
  try {
    answer.message = what;
    ROS_ERROR("%s: no plan (%s): %s", setup_.who.c_str(), toName(PlanOutcome::kInternalError), what);
  } catch (...) {
  }
  return answer;
}

bool RosPlanner::onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response) {
  const auto entered = std::chrono::steady_clock::now();
  try {
    CostmapSnapshot costmap;
    try {
      costmap = setup_.costmap();
    } catch (const std::exception& e) {
      ROS_ERROR("%s: make_plan: no plan (%s): %s", setup_.who.c_str(), toName(PlanOutcome::kBadCostmap), e.what());
      return true;
    }
    const std::string frame = costmap.frame_id;
    response.plan.header.frame_id = frame;
    response.plan.header.stamp = ros::Time::now();
    geometry_msgs::PoseStamped start = request.start, goal = request.goal;
    std::string error;
    for (auto* pose : {&start, &goal}) {
      if (pose->header.frame_id.empty() || pose->header.frame_id == frame) {
        pose->header.frame_id = frame;
      } else if (!setup_.transform || !setup_.transform(geometry_msgs::PoseStamped(*pose), frame, *pose, error)) {
        ROS_ERROR("%s: make_plan: no plan (%s): the %s is in frame '%s', the costmap in '%s'%s%s", setup_.who.c_str(),
                  toName(pose == &start ? PlanOutcome::kStartOffMap : PlanOutcome::kGoalOffMap),
                  pose == &start ? "start" : "goal", pose->header.frame_id.c_str(), frame.c_str(),
                  error.empty() ? "" : ": ", error.c_str());
        return true;
      }
    }
    // The request's own tolerance when > 0, else default_tolerance. A copy: the service that
    // asks holds no costmap lock, and the costmap goes on updating while this plans.
    PlanRequest plan_request = requestFor(start, goal, request.tolerance > 0 ? request.tolerance : -1.0);
    plan_request.called_at = entered;  // max_planning_time bounds the whole call, the copy included
    const PlanReply reply = service_->plan(costmap, plan_request);
    answerFor(reply, start, goal, response.plan.poses, true, entered);
  } catch (const std::exception& e) {
    failedWith(e.what(), response.plan.poses);
  } catch (...) {
    failedWith("an unknown exception", response.plan.poses);
  }
  return true;
}

bool RosPlanner::onCancel(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  try {
    response.success = service_->cancel();
    response.message = response.success ? "cancelling the plan in progress: it stops with the best route so far"
                                         : "no plan in progress";
    ROS_INFO("%s: cancel: %s", setup_.who.c_str(), response.message.c_str());
  } catch (...) {
  }
  return true;
}

bool RosPlanner::onSaveCostmap(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  try {
    ReplayFiles files;
    const std::string error = service_->saveCostmap(setup_.costmap(), files);
    response.success = error.empty() && !files.map_yaml.empty();
    response.message = response.success ? files.map_yaml + (files.command.empty() ? "" : "; replay: " + files.command)
                                        : (error.empty() ? "cannot save the costmap" : error);
  } catch (const std::exception& e) {
    response.success = false;
    response.message = e.what();
  } catch (...) {
    response.success = false;
  }
  return true;
}

}  // namespace eaci_ros
