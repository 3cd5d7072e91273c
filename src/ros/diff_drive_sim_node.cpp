// diff_drive_sim: the paper's WHEELTEC car as a simulated differential-drive robot.
// Integrates Eq. 5-7 (eaci::robot::DiffDriveRobot) from cmd_vel, simulates wheel encoders and
// publishes their dead-reckoning odometry on `odom` with the odom -> base_link transform, and
// the true pose on `~ground_truth`. Given a world map, it carries the paper's laser (an M10P,
// eaci::robot::LaserSpec) and publishes its scans on `scan`, ray-cast from the true pose on that
// map and on boxes the map does not hold (eaci::robot::SimWorld), and how near the car's
// footprint comes to any of it on `~footprint_clearance` (0 = contact).
//
//   ~rate (50 Hz), ~cmd_timeout (0.5 s: stop without fresh commands)
//   ~wheel_base, ~wheel_radius, ~max_wheel_speed, ~max_wheel_accel (robot, m and s)
//   ~ticks_per_revolution (1560), ~encoder_noise_ticks (0), ~seed (1)
//   ~initial_x, ~initial_y, ~initial_yaw (pose in the odom frame, which starts on the world's), ~odom_frame, ~base_frame
//   ~world_map: a map_server YAML of the world the laser sees ("" = no laser); its occupied cells
//     are obstacles, unknown and free ones are not
//   ~boxes: [[x, y, size_x, size_y], ...] more obstacles (m, world frame, axis-aligned)
//   ~moving_box: [x, y, size_x, size_y, to_x, to_y, speed]: a box going from (x, y) to (to_x, to_y)
//     and back at speed m/s from the node's start; it waits while its next step would bring it
//     nearer the car's footprint than ~moving_box_margin (0.1 m) and turns round after 2 s of
//     waiting, as a person would (eaci::robot::BoxWalker)
//   ~laser_frame ("laser", at ~laser_height 0.18 m above base_link), ~scan_rate (12 Hz),
//     ~range_max (30 m), ~range_sigma (0.015 m: the M10P's +-3 cm as two standard deviations)
//   ~footprint_length, ~footprint_width (0.265, 0.205 m: the car, for ~footprint_clearance)
//   ~world_frame ("map"): the frame of the boxes' markers on ~boxes (visualization_msgs/MarkerArray)
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float64.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "eaci/io/map_io.hpp"
#include "eaci/robot/diff_drive.hpp"
#include "eaci/robot/laser_scan.hpp"
#include "eaci/robot/sim_world.hpp"
#include "eaci/robot/wheel_encoders.hpp"

namespace eaci_ros {

using eaci::robot::Pose2;

// ~boxes and ~moving_box as the core's boxes; a clear error for a malformed entry.
std::vector<eaci::robot::Box> readBoxes(const ros::NodeHandle& nh) {
  std::vector<eaci::robot::Box> boxes;
  XmlRpc::XmlRpcValue list;
  if (!nh.getParam("boxes", list)) return boxes;
  const auto number = [](XmlRpc::XmlRpcValue& v) {
    if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<double>(static_cast<int>(v));
    if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) return static_cast<double>(v);
    throw std::invalid_argument("~boxes: every value must be a number");
  };
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray) throw std::invalid_argument("~boxes must be a list of [x, y, size_x, size_y]");
  for (int i = 0; i < list.size(); ++i) {
    if (list[i].getType() != XmlRpc::XmlRpcValue::TypeArray || list[i].size() != 4)
      throw std::invalid_argument("~boxes: entry " + std::to_string(i) + " is not [x, y, size_x, size_y]");
    boxes.push_back({Eigen::Vector2d(number(list[i][0]), number(list[i][1])),
                     Eigen::Vector2d(number(list[i][2]), number(list[i][3]))});
  }
  return boxes;
}

std::optional<eaci::robot::MovingBox> readMovingBox(const ros::NodeHandle& nh) {
  std::vector<double> v;
  if (!nh.getParam("moving_box", v)) return std::nullopt;
  if (v.size() != 7) throw std::invalid_argument("~moving_box must be [x, y, size_x, size_y, to_x, to_y, speed]");
  return eaci::robot::MovingBox{{Eigen::Vector2d(v[0], v[1]), Eigen::Vector2d(v[2], v[3])}, Eigen::Vector2d(v[4], v[5]), v[6]};
}

// The world map's obstacles as the planners read them (OccupancyMap::view); unknown cells are not
// obstacles to the laser.
std::vector<std::uint8_t> occupiedCells(const eaci::OccupancyMap& map) {
  const eaci::GridView view = map.view(eaci::UnknownPolicy::kExpensive);
  std::vector<std::uint8_t> occupied(map.cells.size(), 0);
  for (int row = 0; row < map.height; ++row)
    for (int col = 0; col < map.width; ++col)
      occupied[static_cast<std::size_t>(row) * map.width + col] = view.isObstacle(eaci::Cell{row, col});
  return occupied;
}

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

    setUpLaser();

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
    if (world_) sense(now, dt);
  }

  void setUpLaser() {
    std::string world_map;
    private_nh_.param<std::string>("world_map", world_map, "");
    if (world_map.empty()) return;
    const eaci::OccupancyMap map = eaci::loadMapServerYaml(world_map);
    world_.emplace(map, occupiedCells(map), readBoxes(private_nh_), readMovingBox(private_nh_));
    private_nh_.param<std::string>("laser_frame", laser_frame_, "laser");
    private_nh_.param<std::string>("world_frame", world_frame_, world_frame_);
    private_nh_.param("scan_rate", laser_.scan_rate, laser_.scan_rate);
    private_nh_.param("range_max", laser_.range_max, laser_.range_max);
    private_nh_.param("range_sigma", laser_.range_sigma, laser_.range_sigma);
    private_nh_.param("laser_height", laser_.mount_height, laser_.mount_height);
    int seed = 1;
    private_nh_.param("seed", seed, seed);
    laser_.seed = static_cast<std::uint64_t>(seed) + 1;
    const std::string error = eaci::robot::validationError(laser_);
    if (!error.empty()) throw std::invalid_argument("laser: " + error);
    noise_ = eaci::SplitMix64(laser_.seed);
    double length = 0.265, width = 0.205;
    private_nh_.param("footprint_length", length, length);
    private_nh_.param("footprint_width", width, width);
    private_nh_.param("moving_box_margin", box_margin_, box_margin_);
    footprint_half_ = Eigen::Vector2d(length / 2, width / 2);
    scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 5);
    clearance_pub_ = private_nh_.advertise<std_msgs::Float64>("footprint_clearance", 50);
    boxes_pub_ = private_nh_.advertise<visualization_msgs::MarkerArray>("boxes", 2, true);
    started_ = ros::Time::now();

    geometry_msgs::TransformStamped mount;
    mount.header.stamp = started_;
    mount.header.frame_id = base_frame_;
    mount.child_frame_id = laser_frame_;
    mount.transform.translation.z = laser_.mount_height;
    mount.transform.rotation.w = 1.0;
    static_broadcaster_.sendTransform(mount);
    ROS_INFO("diff_drive_sim: a laser on %s at %.0f Hz sees %s and %zu boxes%s", laser_frame_.c_str(), laser_.scan_rate,
             world_map.c_str(), world_->boxesAt(0).size(), world_->movingBox() ? ", one of them moving" : "");
  }

  // The footprint's clearance every tick; a scan and the boxes when one is due.
  void sense(const ros::Time& now, double dt) {
    // The moving box walks on unless it would come nearer the car than its margin (BoxWalker).
    const Pose2& car = robot_.pose();
    if (const auto& moving = world_->movingBox()) {
      const auto footprint = eaci::robot::corners(car, footprint_half_);
      box_walker_.step(*moving, dt, box_margin_, kBoxPatience, [&](const eaci::robot::Box& b) {
        return eaci::robot::quadDistance(footprint, eaci::robot::corners(b));
      });
    }
    const double t = box_walker_.clock;
    std_msgs::Float64 clearance;
    clearance.data = world_->footprintClearance(car, footprint_half_, t, 1.0);
    clearance_pub_.publish(clearance);
    if (!next_scan_.isZero() && now < next_scan_) return;
    // Scans keep the laser's rate on average, on the ticks at or after each one is due.
    const ros::Duration period(1.0 / laser_.scan_rate);
    next_scan_ = next_scan_.isZero() || now - next_scan_ > period ? now + period : next_scan_ + period;
    sensor_msgs::LaserScan scan;
    scan.header.stamp = now;
    scan.header.frame_id = laser_frame_;
    scan.angle_min = static_cast<float>(laser_.angle_min);
    scan.angle_increment = static_cast<float>(laser_.angle_increment);
    scan.angle_max = static_cast<float>(laser_.angle_min + (laser_.beams - 1) * laser_.angle_increment);
    scan.scan_time = static_cast<float>(1.0 / laser_.scan_rate);
    scan.range_min = static_cast<float>(laser_.range_min);
    scan.range_max = static_cast<float>(laser_.range_max);
    scan.ranges = eaci::robot::castScan(world_->frame(), world_->at(t), car.position, car.orientation.angle(), laser_,
                                        &noise_);
    scan_pub_.publish(scan);
    if (boxes_pub_.getNumSubscribers() > 0 || !boxes_published_) publishBoxes(t, now);
  }

  void publishBoxes(double t, const ros::Time& now) {
    visualization_msgs::MarkerArray markers;
    int id = 0;
    for (const auto& b : world_->boxesAt(t)) {
      visualization_msgs::Marker m;
      m.header.stamp = now;
      m.header.frame_id = world_frame_;
      m.ns = "boxes";
      m.id = id++;
      m.type = visualization_msgs::Marker::CUBE;
      m.pose.position.x = b.centre.x();
      m.pose.position.y = b.centre.y();
      m.pose.position.z = 0.2;
      m.pose.orientation.w = 1.0;
      m.scale.x = b.size.x();
      m.scale.y = b.size.y();
      m.scale.z = 0.4;
      m.color.r = 0.8f, m.color.g = 0.5f, m.color.b = 0.1f, m.color.a = 0.9f;
      markers.markers.push_back(m);
    }
    boxes_pub_.publish(markers);
    boxes_published_ = true;
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
  std::string odom_frame_, base_frame_, laser_frame_, world_frame_ = "map";
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
  // The laser and the world it sees (none without ~world_map).
  std::optional<eaci::robot::SimWorld> world_;
  eaci::robot::LaserSpec laser_;
  eaci::SplitMix64 noise_{1};
  Eigen::Vector2d footprint_half_ = Eigen::Vector2d::Zero();
  ros::Time started_, next_scan_;
  eaci::robot::BoxWalker box_walker_;
  static constexpr double kBoxPatience = 2.0;  // s the moving box waits for the car before it turns round
  double box_margin_ = 0.1;  // m: the moving box does not come nearer the car than this
  bool boxes_published_ = false;
  ros::Publisher scan_pub_, clearance_pub_, boxes_pub_;
  tf2_ros::StaticTransformBroadcaster static_broadcaster_;
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
