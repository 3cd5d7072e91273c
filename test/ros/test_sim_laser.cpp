// Watches diff_drive_sim's laser (sim_laser.test): the car at (0.4, 0.4) facing +x on the lab
// map, whose outer walls are its edge cells (x and y from 0 to 0.05 m), with a box from x = 0.9
// to 1.1 m ahead of it. Ranges are from the laser's centre, the car's.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float64.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;

// The range of the beam nearest `angle` (rad, counter-clockwise from the car's heading).
double rangeAt(const sensor_msgs::LaserScan& scan, double angle) {
  const long k = std::lround((angle - scan.angle_min) / scan.angle_increment);
  return scan.ranges.at(static_cast<std::size_t>(k));
}

}  // namespace

TEST(SimLaser, SeesTheLabsWallsAndTheBoxWhereTheyAre) {
  ros::NodeHandle nh;
  sensor_msgs::LaserScan::ConstPtr scan = ros::topic::waitForMessage<sensor_msgs::LaserScan>("/scan", nh, ros::Duration(20));
  ASSERT_TRUE(scan) << "no scan on /scan within 20 s";
  EXPECT_EQ(scan->header.frame_id, "laser");
  EXPECT_EQ(scan->ranges.size(), 1636u);  // the M10P: 360 degrees in 0.22-degree steps
  EXPECT_FLOAT_EQ(scan->range_max, 30.0f);
  EXPECT_NEAR(rangeAt(*scan, 0.0), 0.9 - 0.4, 1e-4);         // ahead: the box's near face
  EXPECT_NEAR(rangeAt(*scan, -kPi), 0.4 - 0.05, 1e-4);       // behind: the left wall's face
  EXPECT_NEAR(rangeAt(*scan, -kPi / 2), 0.4 - 0.05, 1e-4);   // right: the bottom wall's face
  EXPECT_NEAR(rangeAt(*scan, kPi / 2), 2.95 - 0.4, 1e-4);    // left: the top wall, the lab being 3 m deep
}

TEST(SimLaser, MountsTheLaserAtThePapersHeight) {
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  const geometry_msgs::TransformStamped mount = buffer.lookupTransform("base_link", "laser", ros::Time(0), ros::Duration(10));
  EXPECT_NEAR(mount.transform.translation.x, 0.0, 1e-9);
  EXPECT_NEAR(mount.transform.translation.z, 0.18, 1e-9);
}

// The car's back (0.4 - 0.1325 m) is the nearest to a wall: the left wall's face at x = 0.05.
TEST(SimLaser, ReportsTheFootprintsClearanceFromTheWorld) {
  ros::NodeHandle nh;
  std_msgs::Float64::ConstPtr clearance =
      ros::topic::waitForMessage<std_msgs::Float64>("/diff_drive_sim/footprint_clearance", nh, ros::Duration(20));
  ASSERT_TRUE(clearance);
  EXPECT_NEAR(clearance->data, 0.4 - 0.1325 - 0.05, 1e-9);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_sim_laser");
  return RUN_ALL_TESTS();
}
