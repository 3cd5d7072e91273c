// diff_drive_sim: the paper's WHEELTEC car as a simulated differential-drive robot.
// Integrates Eq. 5-7 (eaci::robot::DiffDriveRobot) from cmd_vel, simulates wheel encoders and
// publishes their dead-reckoning odometry on `odom` with the odom -> base_link transform, and
// the true pose on `~ground_truth`.
//
//   ~rate (50 Hz), ~cmd_timeout (0.5 s: stop without fresh commands)
//   ~wheel_base, ~wheel_radius, ~max_wheel_speed, ~max_wheel_accel (robot, m and s)
//   ~ticks_per_revolution (1560), ~encoder_noise_ticks (0), ~seed (1)
//   ~initial_x, ~initial_y, ~initial_yaw (pose in the odom frame), ~odom_frame, ~base_frame
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_ros/transform_broadcaster.h>

#include <string>

#include "eaci/robot/diff_drive.hpp"
#include "eaci/robot/wheel_encoders.hpp"

namespace eaci_ros {

using eaci::robot::Pose2;

class DiffDriveSim {
 public:
  DiffDriveSim() : private_nh_("~") {
    eaci::robot::DiffDriveParams robot;
    private_nh_.param("wheel_base", robot.wheel_base, robot.wheel_base);
    private_nh_.param("wheel_radius", robot.wheel_radius, robot.wheel_radius);
    private_nh_.param("max_wheel_speed", robot.max_wheel_speed, robot.max_wheel_speed);
    private_nh_.param("max_wheel_accel", robot.max_wheel_accel, robot.max_wheel_accel);
    eaci::robot::validate(robot);
    eaci::robot::EncoderParams encoders;
    private_nh_.param("ticks_per_revolution", encoders.ticks_per_revolution, encoders.ticks_per_revolution);
    private_nh_.param("encoder_noise_ticks", encoders.noise_ticks, encoders.noise_ticks);
    int seed = 1;
    private_nh_.param("seed", seed, seed);
    encoders.seed = static_cast<std::uint64_t>(seed);
    eaci::robot::validate(encoders);
    Pose2 start;
    private_nh_.param("initial_x", start.position.x(), 0.0);
    private_nh_.param("initial_y", start.position.y(), 0.0);
    private_nh_.param("initial_yaw", start.orientation.angle(), 0.0);
    private_nh_.param<std::string>("odom_frame", odom_frame_, "odom");
    private_nh_.param<std::string>("base_frame", base_frame_, "base_link");
    double rate = 50.0;
    private_nh_.param("rate", rate, rate);
    private_nh_.param("cmd_timeout", cmd_timeout_, 0.5);
    if (!(rate > 0)) throw std::invalid_argument("~rate must be > 0");

    robot_ = eaci::robot::DiffDriveRobot(robot, start);
    encoders_ = eaci::robot::WheelEncoders(encoders);
    odometry_ = eaci::robot::EncoderOdometry(encoders.ticks_per_revolution, robot.wheel_radius, robot.wheel_base);
    odometry_.reset(start, encoders_.counts());

    odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", 10);
    truth_pub_ = private_nh_.advertise<nav_msgs::Odometry>("ground_truth", 10);
    cmd_sub_ = nh_.subscribe("cmd_vel", 10, &DiffDriveSim::onCommand, this);
    timer_ = nh_.createTimer(ros::Duration(1.0 / rate), &DiffDriveSim::onTick, this);
  }

 private:
  void onCommand(const geometry_msgs::Twist::ConstPtr& cmd) {
    command_ = *cmd;
    last_command_ = ros::Time::now();
  }

  void onTick(const ros::TimerEvent& event) {
    const double dt = event.last_real.isZero() ? 0.0 : (event.current_real - event.last_real).toSec();
    if (dt <= 0) return;
    const bool fresh = !last_command_.isZero() && (ros::Time::now() - last_command_).toSec() <= cmd_timeout_;
    const double left_before = robot_.leftWheelAngle(), right_before = robot_.rightWheelAngle();
    robot_.step(fresh ? command_.linear.x : 0.0, fresh ? command_.angular.z : 0.0, dt);
    encoders_.rotate(robot_.leftWheelAngle() - left_before, robot_.rightWheelAngle() - right_before);
    const Pose2& estimate = odometry_.update(encoders_.counts());
    const ros::Time now = ros::Time::now();
    odom_pub_.publish(odometryMessage(estimate, odometry_.lastDistance() / dt, odometry_.lastRotation() / dt, now));
    const auto twist = robot_.twist();
    truth_pub_.publish(odometryMessage(robot_.pose(), twist.v, twist.omega, now));
    broadcastTransform(estimate, now);
  }

  nav_msgs::Odometry odometryMessage(const Pose2& pose, double v, double omega, const ros::Time& stamp) const {
    nav_msgs::Odometry odom;
    odom.header.stamp = stamp;
    odom.header.frame_id = odom_frame_;
    odom.child_frame_id = base_frame_;
    odom.pose.pose.position.x = pose.position.x();
    odom.pose.pose.position.y = pose.position.y();
    tf2::Quaternion q;
    q.setRPY(0, 0, pose.orientation.angle());
    odom.pose.pose.orientation = tf2::toMsg(q);
    odom.twist.twist.linear.x = v;
    odom.twist.twist.angular.z = omega;
    return odom;
  }

  void broadcastTransform(const Pose2& pose, const ros::Time& stamp) {
    geometry_msgs::TransformStamped t;
    t.header.stamp = stamp;
    t.header.frame_id = odom_frame_;
    t.child_frame_id = base_frame_;
    t.transform.translation.x = pose.position.x();
    t.transform.translation.y = pose.position.y();
    tf2::Quaternion q;
    q.setRPY(0, 0, pose.orientation.angle());
    t.transform.rotation = tf2::toMsg(q);
    tf_broadcaster_.sendTransform(t);
  }

  ros::NodeHandle nh_, private_nh_;
  std::string odom_frame_, base_frame_;
  double cmd_timeout_ = 0.5;
  eaci::robot::DiffDriveRobot robot_;
  eaci::robot::WheelEncoders encoders_;
  eaci::robot::EncoderOdometry odometry_{1, 1.0, 1.0};
  geometry_msgs::Twist command_;
  ros::Time last_command_;
  ros::Publisher odom_pub_, truth_pub_;
  ros::Subscriber cmd_sub_;
  ros::Timer timer_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
};

}  // namespace eaci_ros

int main(int argc, char** argv) {
  ros::init(argc, argv, "diff_drive_sim");
  try {
    eaci_ros::DiffDriveSim sim;
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("diff_drive_sim: %s", e.what());
    return 1;
  }
  return 0;
}
