// eaci_planner_node: EACI on a saved map or the /map topic, as a nav_msgs/GetPlan service.
//
//   ~map_file (string)   map_server YAML to load; empty -> subscribe to `map`
//   ~frame_id (string)   frame of a map loaded from ~map_file (default "map"); it is
//                        published latched on `map` for RViz and other nodes
//   every core parameter and the ROS options of ros_parameters.hpp under ~ (~robot_radius
//   grows the obstacles so that a robot of that radius, planned as a point, keeps clear;
//   ~inflation_radius > 0 and ~cost_scaling_factor add costmap_2d's inflation costs around them,
//   so routes keep off walls as move_base's do);
//   dynamic_reconfigure (cfg/EaciPlanner.cfg) changes them at run time, between two plans. A bad
//   value is named on every request, which fails, until it is fixed (planner_configuration.hpp).
// Services: ~make_plan (nav_msgs/GetPlan), ~cancel (std_srvs/Trigger: the plan in progress
// stops at its next iteration and answers with the best route so far). Topics: ~plan
// (nav_msgs/Path), ~pheromone (nav_msgs/OccupancyGrid, with ~visualize_pheromone).
//
// Threads: two spinner threads serve make_plan and the map topic (make_plan calls and map
// updates take turns on one mutex); ~cancel has a callback queue and a thread of its own, so
// it is answered while every other thread waits for a plan.
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <mutex>
#include <string>

#include "eaci/io/map_io.hpp"
#include "grid_planner.hpp"
#include "plan_cancellation.hpp"
#include "planner_configuration.hpp"

namespace eaci_ros {

class PlannerNode {
 public:
  PlannerNode() : private_nh_("~"), tf_listener_(tf_buffer_), config_(private_nh_, mutex_, "eaci_planner_node") {
    plan_pub_ = private_nh_.advertise<nav_msgs::Path>("plan", 1, true);
    pheromone_pub_ = private_nh_.advertise<nav_msgs::OccupancyGrid>("pheromone", 1, true);
    std::string map_file;
    private_nh_.param<std::string>("map_file", map_file, "");
    if (!map_file.empty()) {
      std::string frame_id;
      private_nh_.param<std::string>("frame_id", frame_id, "map");
      const nav_msgs::OccupancyGrid loaded = toOccupancyGrid(eaci::loadMap(map_file), frame_id);
      setMap(loaded);
      map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
      map_pub_.publish(loaded);
      ROS_INFO("eaci_planner_node: loaded %s (%u x %u cells, %.3f m)", map_file.c_str(), map_.info.width,
               map_.info.height, map_.info.resolution);
    } else {
      map_sub_ = nh_.subscribe("map", 1, &PlannerNode::onMap, this);
      ROS_INFO("eaci_planner_node: waiting for a map on %s", map_sub_.getTopic().c_str());
    }
    service_ = private_nh_.advertiseService("make_plan", &PlannerNode::onMakePlan, this);
    ros::NodeHandle cancel_nh("~");
    cancel_nh.setCallbackQueue(&cancel_queue_);
    cancel_service_ = cancel_nh.advertiseService("cancel", &PlannerNode::onCancel, this);
    cancel_spinner_.start();
  }

 private:
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& map) {
    std::lock_guard<std::mutex> lock(mutex_);
    setMap(*map);
    ROS_INFO("eaci_planner_node: new map %u x %u cells at %.3f m in frame %s", map_.info.width, map_.info.height,
             map_.info.resolution, map_.header.frame_id.c_str());
  }

  void setMap(const nav_msgs::OccupancyGrid& map) {
    map_ = map;
    if (map_.header.frame_id.empty()) map_.header.frame_id = "map";
    const RosPlannerOptions& options = config_.options();
    costs_.clear();
    if (options.inflation_radius > 0) {
      eaci::InflationParameters inflation;
      inflation.inflation_radius = options.inflation_radius;
      inflation.inscribed_radius = options.robot_radius;
      inflation.cost_scaling_factor = options.cost_scaling_factor;
      costs_ = inflatedCostsOf(map_, options.occupied_threshold, inflation);
    } else {
      inflateObstacles(map_, options.robot_radius, options.occupied_threshold);
    }
    have_map_ = map_.data.size() == static_cast<std::size_t>(map_.info.width) * map_.info.height &&
                !map_.data.empty() && map_.info.resolution > 0;
    if (!have_map_) ROS_ERROR("eaci_planner_node: the map is empty or malformed; plans will fail until a good one arrives");
  }

  // Pose in the map frame, or false with the reason.
  bool inMapFrame(const geometry_msgs::PoseStamped& pose, const char* what, geometry_msgs::PoseStamped& out,
                  std::string& error) {
    if (pose.header.frame_id.empty() || pose.header.frame_id == map_.header.frame_id) {
      out = pose;
      out.header.frame_id = map_.header.frame_id;
      return true;
    }
    try {
      out = tf_buffer_.transform(pose, map_.header.frame_id, ros::Duration(0.2));
      return true;
    } catch (const tf2::TransformException& e) {
      error = std::string(what) + " is in frame '" + pose.header.frame_id + "', which cannot be transformed to '" +
              map_.header.frame_id + "': " + e.what();
      return false;
    }
  }

  // Cancels the plan in progress, if any; a make_plan call still waiting for its turn is not
  // affected.
  bool onCancel(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
    response.success = cancellation_.cancel();
    response.message = response.success
                           ? "cancelling the plan in progress: it stops at its next iteration with the best route so far"
                           : "no plan in progress";
    ROS_INFO("eaci_planner_node: cancel: %s", response.message.c_str());
    return true;
  }

  bool onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response) {
    std::lock_guard<std::mutex> lock(mutex_);
    const PlanCancellation::Scope in_progress(cancellation_);
    response.plan.header.frame_id = map_.header.frame_id;
    response.plan.header.stamp = ros::Time::now();
    if (!config_.error().empty()) {
      ROS_ERROR("eaci_planner_node: make_plan: %s: refusing to plan until it is fixed", config_.error().c_str());
      return true;
    }
    if (!have_map_) {
      ROS_ERROR("eaci_planner_node: make_plan: no map yet");
      return true;
    }
    const eaci::Parameters& params = config_.params();
    const RosPlannerOptions& options = config_.options();
    geometry_msgs::PoseStamped start, goal;
    std::string error;
    if (!inMapFrame(request.start, "start", start, error) || !inMapFrame(request.goal, "goal", goal, error)) {
      ROS_ERROR("eaci_planner_node: make_plan: %s", error.c_str());
      return true;
    }
    const double tolerance = request.tolerance > 0 ? request.tolerance : options.default_tolerance;
    const eaci::GridView view =
        costs_.empty() ? viewOf(map_, options.occupied_threshold, params.allow_unknown)
                       : costView(costs_, static_cast<int>(map_.info.width), static_cast<int>(map_.info.height),
                                  params.lethal_cost, params.allow_unknown);
    const GridPlan plan =
        planOnGrid(view, frameOf(map_), start, goal, tolerance, params, options, cancellation_.flag(), &workspace_);
    if (!plan.ok) {
      ROS_WARN("eaci_planner_node: make_plan: %s", plan.error.c_str());
      return true;
    }
    ROS_INFO("eaci_planner_node: %s route of %.3f m (%zu poses, %d islands, %d iterations, %lld lost ants)%s%s",
             eaci::toString(options.algorithm), plan.result.length * map_.info.resolution, plan.path.poses.size(),
             static_cast<int>(plan.result.islands.size()), plan.result.iterations_run, plan.result.lost_ants_total,
             plan.stopped_by == StopReason::kNone ? "" : ", the best so far: ",
             plan.stopped_by == StopReason::kNone ? "" : toString(plan.stopped_by));
    response.plan = plan.path;
    if (options.publish_plan) plan_pub_.publish(plan.path);
    if (options.visualize_pheromone && !plan.result.pheromone.empty())
      pheromone_pub_.publish(fieldToGrid(plan.result.pheromone, frameOf(map_), ros::Time::now()));
    return true;
  }

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  std::mutex mutex_;  // plans, map updates and new parameters take turns
  PlannerConfiguration config_;  // read and changed under mutex_
  nav_msgs::OccupancyGrid map_;
  std::vector<std::uint8_t> costs_;  // with ~inflation_radius: map_ as costmap_2d costs, row 0 = top
  bool have_map_ = false;
  ros::Subscriber map_sub_;
  ros::Publisher map_pub_, plan_pub_, pheromone_pub_;
  ros::ServiceServer service_;
  // ~cancel: its own queue and thread.
  PlanCancellation cancellation_;
  eaci::PlannerWorkspace workspace_;  // buffers and threads kept from plan to plan, used under mutex_
  ros::CallbackQueue cancel_queue_;
  ros::AsyncSpinner cancel_spinner_{1, &cancel_queue_};
  ros::ServiceServer cancel_service_;
};

}  // namespace eaci_ros

int main(int argc, char** argv) {
  ros::init(argc, argv, "eaci_planner_node");
  try {
    eaci_ros::PlannerNode node;
    ros::AsyncSpinner spinner(2);  // a second make_plan or a map waits on the node's mutex, not in the queue
    spinner.start();
    ros::waitForShutdown();
  } catch (const std::exception& e) {
    ROS_FATAL("eaci_planner_node: %s", e.what());
    return 1;
  }
  return 0;
}
