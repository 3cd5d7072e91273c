// A pose in a frame (the map's by default), facing along x: the requests the ROS tests send.
#pragma once

#include <string>

#include <geometry_msgs/PoseStamped.h>

namespace eaci_test {

inline geometry_msgs::PoseStamped mapPose(double x, double y, const std::string& frame = "map") {
  geometry_msgs::PoseStamped p;
  p.header.frame_id = frame;
  p.pose.position.x = x;
  p.pose.position.y = y;
  p.pose.orientation.w = 1.0;
  return p;
}

}  // namespace eaci_test
