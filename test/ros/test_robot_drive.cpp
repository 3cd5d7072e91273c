// Watches the demo (robot_drive.test): the simulated robot, driven by the PID follower along
// EACI's route, reaches the goal, and neither its centre nor its footprint ever covers an obstacle cell.
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <tf2/utils.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "eaci/io/map_io.hpp"

namespace {

struct Watch {
  eaci::OccupancyMap map;
  bool arrived = false;
  int poses = 0;
  int collisions = 0;
  double last_x = 0.0, last_y = 0.0;
  std::string first_collision;
  double min_clearance = 1e9;  // m, from the centre to the nearest occupied cell's centre

  // The distance from (x, y) to the nearest occupied cell centre within 1 m (1 m if none).
  double clearance(double x, double y) const {
    const auto cell = map.worldToCell({x, y});
    if (!cell) return 0.0;
    const int reach = static_cast<int>(std::ceil(1.0 / map.resolution));
    double best = 1.0;
    for (int r = std::max(0, cell->row - reach); r <= std::min(map.height - 1, cell->row + reach); ++r)
      for (int c = std::max(0, cell->col - reach); c <= std::min(map.width - 1, cell->col + reach); ++c) {
        if (map.cells[static_cast<std::size_t>(r) * map.width + c] == eaci::kFreeValue) continue;
        const Eigen::Vector2d centre = map.cellToWorld(eaci::Cell{r, c});
        best = std::min(best, std::hypot(centre.x() - x, centre.y() - y));
      }
    return best;
  }

  bool obstacleAt(double x, double y) const {
    const auto cell = map.worldToCell({x, y});
    return !cell || map.cells[static_cast<std::size_t>(cell->row) * map.width + cell->col] != eaci::kFreeValue;
  }

  // The robot's centre and the corners of its 265 x 205 mm footprint.
  void onTruth(const nav_msgs::Odometry::ConstPtr& odom) {
    const double x = odom->pose.pose.position.x, y = odom->pose.pose.position.y;
    const double yaw = tf2::getYaw(odom->pose.pose.orientation);
    ++poses;
    last_x = x;
    last_y = y;
    min_clearance = std::min(min_clearance, clearance(x, y));
    const double c = std::cos(yaw), s = std::sin(yaw);
    const double corners[5][2] = {{0, 0}, {0.1325, 0.1025}, {0.1325, -0.1025}, {-0.1325, 0.1025}, {-0.1325, -0.1025}};
    for (const auto& k : corners) {
      const double px = x + c * k[0] - s * k[1], py = y + s * k[0] + c * k[1];
      if (!obstacleAt(px, py)) continue;
      if (collisions++ == 0) first_collision = "(" + std::to_string(px) + ", " + std::to_string(py) + ")";
    }
  }
};

}  // namespace

TEST(RobotDrive, ReachesTheGoalWithoutTouchingAnObstacle) {
  ros::NodeHandle nh, private_nh("~");
  std::string file;
  ASSERT_TRUE(private_nh.getParam("map_file", file));
  double goal_x = 0, goal_y = 0;
  ASSERT_TRUE(private_nh.getParam("goal_x", goal_x));
  ASSERT_TRUE(private_nh.getParam("goal_y", goal_y));
  Watch watch;
  watch.map = eaci::loadMap(file);
  auto truth = nh.subscribe<nav_msgs::Odometry>("/diff_drive_sim/ground_truth", 100, &Watch::onTruth, &watch);
  auto arrived = nh.subscribe<std_msgs::Bool>("/pid_path_follower/arrived", 10,
                                              [&](const std_msgs::Bool::ConstPtr& m) { watch.arrived = m->data; });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(120.0);
  ros::WallRate rate(50.0);
  while (ros::ok() && !watch.arrived && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    rate.sleep();
  }
  for (int k = 0; k < 10; ++k) {  // a few more ground-truth poses after arrival
    ros::spinOnce();
    rate.sleep();
  }
  EXPECT_TRUE(watch.arrived) << "no arrival within 120 s; last pose (" << watch.last_x << ", " << watch.last_y << ")";
  EXPECT_GT(watch.poses, 100);
  EXPECT_EQ(watch.collisions, 0) << "first contact at " << watch.first_collision;
  // The planner costs the lab like move_base's costmap (robot_radius 0.17 m inscribed, inflation
  // to 0.30 m): the cheapest route keeps to the middle of the lab's 0.6 m gaps, so the car's
  // centre keeps at least `min_clearance` from every obstacle cell centre (robot_drive.test).
  double min_clearance = 0.0;
  private_nh.param("min_clearance", min_clearance, 0.0);
  std::printf("robot_drive: minimum clearance of the car's centre %.3f m\n", watch.min_clearance);
  EXPECT_GE(watch.min_clearance, min_clearance);
  // The follower's goal tolerance is 5 cm on odometry; the noise-free encoders add millimetres.
  EXPECT_LT(std::hypot(watch.last_x - goal_x, watch.last_y - goal_y), 0.08);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_robot_drive");
  return RUN_ALL_TESTS();
}
