// pid_path_follower: drives the robot along a nav_msgs/Path with PID control of heading and
// distance (eaci::robot::PathFollower), turning in place at sharp corners as the paper's DDMR does.
//
// In:  `path` (nav_msgs/Path, any frame tf can bring into ~odom_frame), `odom` (nav_msgs/Odometry),
//      `goal` (geometry_msgs/PoseStamped: asks ~planner_service for a path from the robot, then follows it)
// Out: `cmd_vel`, `~arrived` (std_msgs/Bool, latched), `~state` (std_msgs/String)
// Params: ~rate (20 Hz), ~odom_frame, ~base_frame, ~planner_service (/eaci_planner_node/make_plan),
//      ~goal ([x, y, yaw] in ~goal_frame, planned for at start-up), ~goal_frame (map),
//      ~max_linear_speed, ~max_angular_speed, ~lookahead_distance, ~waypoint_tolerance,
//      ~goal_tolerance, ~yaw_tolerance, ~rotate_in_place_threshold (rad), ~align_final_yaw
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/String.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "eaci/robot/path_follower.hpp"

namespace eaci_ros {

// Keeps the first and last pose and every pose where the direction changes: a grid path's
// straight runs become single segments.
std::vector<Eigen::Vector2d> cornerPoints(const std::vector<Eigen::Vector2d>& points) {
  if (points.size() < 3) return points;
  std::vector<Eigen::Vector2d> corners{points.front()};
  for (std::size_t k = 1; k + 1 < points.size(); ++k) {
    const Eigen::Vector2d in = points[k] - points[k - 1], out = points[k + 1] - points[k];
    const double cross = in.x() * out.y() - in.y() * out.x();
    const double lengths = std::hypot(in.x(), in.y()) * std::hypot(out.x(), out.y());
    if (std::abs(cross) > 1e-9 * (lengths + 1e-12)) corners.push_back(points[k]);
  }
  corners.push_back(points.back());
  return corners;
}

class PidPathFollowerNode {
 public:
  PidPathFollowerNode() : private_nh_("~"), tf_listener_(tf_buffer_) {
    eaci::robot::PathFollowerParams p;
    private_nh_.param("max_linear_speed", p.max_linear_speed, p.max_linear_speed);
    private_nh_.param("max_angular_speed", p.max_angular_speed, p.max_angular_speed);
    private_nh_.param("lookahead_distance", p.lookahead_distance, p.lookahead_distance);
    private_nh_.param("waypoint_tolerance", p.waypoint_tolerance, p.waypoint_tolerance);
    private_nh_.param("goal_tolerance", p.goal_tolerance, p.goal_tolerance);
    private_nh_.param("yaw_tolerance", p.yaw_tolerance, p.yaw_tolerance);
    private_nh_.param("rotate_in_place_threshold", p.rotate_in_place_threshold, p.rotate_in_place_threshold);
    private_nh_.param("align_final_yaw", p.align_final_yaw, p.align_final_yaw);
    follower_ = eaci::robot::PathFollower(p);
    private_nh_.param<std::string>("odom_frame", odom_frame_, "odom");
    private_nh_.param<std::string>("base_frame", base_frame_, "base_link");
    private_nh_.param<std::string>("planner_service", planner_service_, "/eaci_planner_node/make_plan");
    private_nh_.param<std::string>("goal_frame", goal_frame_, "map");
    double rate = 20.0;
    private_nh_.param("rate", rate, rate);

    cmd_pub_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 10);
    arrived_pub_ = private_nh_.advertise<std_msgs::Bool>("arrived", 1, true);
    state_pub_ = private_nh_.advertise<std_msgs::String>("state", 1, true);
    followed_pub_ = private_nh_.advertise<nav_msgs::Path>("followed_path", 1, true);
    odom_sub_ = nh_.subscribe("odom", 10, &PidPathFollowerNode::onOdometry, this);
    path_sub_ = nh_.subscribe("path", 1, &PidPathFollowerNode::onPath, this);
    goal_sub_ = nh_.subscribe("goal", 1, &PidPathFollowerNode::onGoal, this);
    publishArrived(false);

    std::vector<double> goal;
    if (private_nh_.getParam("goal", goal)) {
      if (goal.size() < 2) throw std::invalid_argument("~goal must be [x, y] or [x, y, yaw]");
      geometry_msgs::PoseStamped pose;
      pose.header.frame_id = goal_frame_;
      pose.pose.position.x = goal[0];
      pose.pose.position.y = goal[1];
      tf2::Quaternion q;
      q.setRPY(0, 0, goal.size() > 2 ? goal[2] : 0.0);
      pose.pose.orientation = tf2::toMsg(q);
      pending_goal_ = pose;
    }
    timer_ = nh_.createTimer(ros::Duration(1.0 / rate), &PidPathFollowerNode::onTick, this);
  }

 private:
  void onOdometry(const nav_msgs::Odometry::ConstPtr& odom) {
    pose_ = eaci::robot::Pose2{{odom->pose.pose.position.x, odom->pose.pose.position.y},
                               Eigen::Rotation2Dd(tf2::getYaw(odom->pose.pose.orientation))};
  }

  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& goal) {
    pending_goal_ = *goal;
    if (pending_goal_->header.frame_id.empty()) pending_goal_->header.frame_id = goal_frame_;
  }

  void onPath(const nav_msgs::Path::ConstPtr& path) { follow(*path); }

  // Brings the path into the odom frame and hands it to the follower.
  bool follow(const nav_msgs::Path& path) {
    std::vector<Eigen::Vector2d> points;
    std::optional<double> goal_yaw;
    try {
      for (const auto& pose : path.poses) {
        geometry_msgs::PoseStamped stamped = pose;
        if (stamped.header.frame_id.empty()) stamped.header.frame_id = path.header.frame_id;
        stamped.header.stamp = ros::Time(0);
        const auto in_odom = tf_buffer_.transform(stamped, odom_frame_, ros::Duration(0.5));
        points.push_back({in_odom.pose.position.x, in_odom.pose.position.y});
        goal_yaw = tf2::getYaw(in_odom.pose.orientation);
      }
    } catch (const tf2::TransformException& e) {
      ROS_ERROR("pid_path_follower: cannot bring the path into %s: %s", odom_frame_.c_str(), e.what());
      return false;
    }
    const std::vector<Eigen::Vector2d> corners = cornerPoints(points);
    follower_.setPath(corners, goal_yaw);
    publishArrived(false);
    nav_msgs::Path followed;
    followed.header.frame_id = odom_frame_;
    followed.header.stamp = ros::Time::now();
    for (const Eigen::Vector2d& p : corners) {
      geometry_msgs::PoseStamped pose;
      pose.header = followed.header;
      pose.pose.position.x = p.x();
      pose.pose.position.y = p.y();
      pose.pose.orientation.w = 1.0;
      followed.poses.push_back(pose);
    }
    followed_pub_.publish(followed);
    ROS_INFO("pid_path_follower: following %zu poses (%zu corners)", points.size(), corners.size());
    return true;
  }

  // Asks the planner for a route from the robot to the pending goal; retried each tick until it answers.
  void requestPlan() {
    if (!pose_ || !ros::service::exists(planner_service_, false)) return;
    nav_msgs::GetPlan srv;
    try {
      geometry_msgs::PoseStamped here;
      here.header.frame_id = odom_frame_;
      here.pose.position.x = pose_->position.x();
      here.pose.position.y = pose_->position.y();
      tf2::Quaternion q;
      q.setRPY(0, 0, pose_->orientation.angle());
      here.pose.orientation = tf2::toMsg(q);
      srv.request.start = tf_buffer_.transform(here, pending_goal_->header.frame_id, ros::Duration(0.5));
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(2.0, "pid_path_follower: waiting for %s -> %s: %s", odom_frame_.c_str(),
                        pending_goal_->header.frame_id.c_str(), e.what());
      return;
    }
    srv.request.goal = *pending_goal_;
    const auto goal = pending_goal_;
    pending_goal_.reset();
    if (!ros::service::call(planner_service_, srv) || srv.response.plan.poses.empty()) {
      ROS_ERROR("pid_path_follower: %s found no path to (%.2f, %.2f)", planner_service_.c_str(),
                goal->pose.position.x, goal->pose.position.y);
      return;
    }
    follow(srv.response.plan);
  }

  void onTick(const ros::TimerEvent& event) {
    if (pending_goal_) requestPlan();
    if (!pose_) return;
    const double dt = event.last_real.isZero() ? 0.0 : (event.current_real - event.last_real).toSec();
    const auto command = follower_.compute(*pose_, dt);
    geometry_msgs::Twist twist;
    twist.linear.x = command.v;
    twist.angular.z = command.omega;
    if (command.state != eaci::robot::FollowerState::kIdle || last_state_ != eaci::robot::FollowerState::kIdle)
      cmd_pub_.publish(twist);
    if (command.state != last_state_) {
      std_msgs::String state;
      state.data = eaci::robot::toString(command.state);
      state_pub_.publish(state);
      if (command.state == eaci::robot::FollowerState::kArrived) {
        ROS_INFO("pid_path_follower: arrived at (%.3f, %.3f)", pose_->position.x(), pose_->position.y());
        publishArrived(true);
      }
      last_state_ = command.state;
    }
  }

  void publishArrived(bool arrived) {
    std_msgs::Bool msg;
    msg.data = arrived;
    arrived_pub_.publish(msg);
  }

  ros::NodeHandle nh_, private_nh_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  eaci::robot::PathFollower follower_;
  std::string odom_frame_, base_frame_, planner_service_, goal_frame_;
  std::optional<eaci::robot::Pose2> pose_;
  std::optional<geometry_msgs::PoseStamped> pending_goal_;
  eaci::robot::FollowerState last_state_ = eaci::robot::FollowerState::kIdle;
  ros::Publisher cmd_pub_, arrived_pub_, state_pub_, followed_pub_;
  ros::Subscriber odom_sub_, path_sub_, goal_sub_;
  ros::Timer timer_;
};

}  // namespace eaci_ros

int main(int argc, char** argv) {
  ros::init(argc, argv, "pid_path_follower");
  try {
    eaci_ros::PidPathFollowerNode node;
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("pid_path_follower: %s", e.what());
    return 1;
  }
  return 0;
}
