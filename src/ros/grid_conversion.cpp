#include "grid_conversion.hpp"

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <limits>

#include "eaci/grid/distance_transform.hpp"

namespace eaci_ros {

TfMapFrame frameOf(const nav_msgs::OccupancyGrid& grid) {
  TfMapFrame f;
  f.frame_id = grid.header.frame_id;
  f.origin = {grid.info.origin.position.x, grid.info.origin.position.y};
  f.origin_yaw = tf2::getYaw(grid.info.origin.orientation);
  f.resolution = grid.info.resolution;
  f.width = static_cast<int>(grid.info.width);
  f.height = static_cast<int>(grid.info.height);
  return f;
}

nav_msgs::OccupancyGrid toOccupancyGrid(const eaci::OccupancyMap& map, const std::string& frame_id) {
  if (map.values != eaci::CellValues::kOccupancy)
    throw std::invalid_argument("a map of costmap costs (mode: raw) has no occupancy values to publish; plan on it "
                                "with eaci_plan, or give a trinary map");
  nav_msgs::OccupancyGrid grid;
  grid.header.frame_id = frame_id;
  grid.info.resolution = static_cast<float>(map.resolution);
  grid.info.width = static_cast<std::uint32_t>(map.width);
  grid.info.height = static_cast<std::uint32_t>(map.height);
  grid.info.origin.position.x = map.origin.x();
  grid.info.origin.position.y = map.origin.y();
  tf2::Quaternion q;
  q.setRPY(0, 0, map.origin_yaw);
  grid.info.origin.orientation = tf2::toMsg(q);
  grid.data.resize(map.cells.size());
  for (int row = 0; row < map.height; ++row) {
    for (int col = 0; col < map.width; ++col) {
      const std::uint8_t v = map.cells[static_cast<std::size_t>(row) * map.width + col];
      const std::size_t out = static_cast<std::size_t>(map.height - 1 - row) * map.width + col;
      grid.data[out] = v == eaci::kUnknownValue ? std::int8_t{-1} : static_cast<std::int8_t>(v);
    }
  }
  return grid;
}

eaci::GridView viewOf(const nav_msgs::OccupancyGrid& grid, int occupied_threshold, bool allow_unknown) {
  eaci::CellInterpretation interpretation;
  interpretation.lethal_cost = static_cast<std::uint8_t>(std::clamp(occupied_threshold, 1, 100));
  interpretation.unknown_value = eaci::kCostmapUnknown;  // int8 -1 read as a byte
  interpretation.unknown = allow_unknown ? eaci::UnknownPolicy::kExpensive : eaci::UnknownPolicy::kObstacle;
  const std::size_t cells = static_cast<std::size_t>(grid.info.width) * grid.info.height;
  if (grid.data.size() != cells || cells == 0) return eaci::GridView();
  return eaci::GridView(reinterpret_cast<const std::uint8_t*>(grid.data.data()), static_cast<int>(grid.info.width),
                        static_cast<int>(grid.info.height), eaci::RowOrder::kBottomFirst, interpretation);
}

void inflateObstacles(nav_msgs::OccupancyGrid& grid, double radius, int occupied_threshold) {
  if (!(radius > 0) || !(grid.info.resolution > 0)) return;
  const int w = static_cast<int>(grid.info.width), h = static_cast<int>(grid.info.height);
  if (grid.data.size() != static_cast<std::size_t>(w) * h) return;
  std::vector<std::uint8_t> occupied(grid.data.size(), 0);
  for (std::size_t i = 0; i < occupied.size(); ++i) occupied[i] = grid.data[i] >= occupied_threshold ? 1 : 0;
  // Row order does not matter here: distances are the same in both.
  const std::vector<double> squared = eaci::squaredDistancesToSources(w, h, occupied);
  const double r = radius / grid.info.resolution;
  for (std::size_t i = 0; i < squared.size(); ++i)
    if (std::sqrt(squared[i]) <= r) grid.data[i] = 100;
}

std::vector<std::uint8_t> inflatedCostsOf(const nav_msgs::OccupancyGrid& grid, int occupied_threshold,
                                          const eaci::InflationParameters& inflation) {
  const eaci::GridView view = viewOf(grid, occupied_threshold, /*allow_unknown=*/false);
  if (view.empty() || !(grid.info.resolution > 0)) return {};
  return eaci::inflatedCosts(view, grid.info.resolution, inflation);
}

nav_msgs::Path toPath(const std::vector<Eigen::Vector2d>& points, const std::string& frame_id,
                      const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                      const ros::Time& stamp, eaci::OrientationMode orientation) {
  nav_msgs::Path path;
  path.header.frame_id = frame_id;
  path.header.stamp = stamp;
  if (points.empty()) return path;
  const std::vector<double> headings =
      eaci::orientPoints(points, tf2::getYaw(start.pose.orientation), tf2::getYaw(goal.pose.orientation), orientation);
  for (std::size_t k = 0; k < points.size(); ++k) {
    geometry_msgs::PoseStamped pose;
    pose.header = path.header;
    pose.pose.position.x = points[k].x();
    pose.pose.position.y = points[k].y();
    if (k + 1 < points.size()) {
      tf2::Quaternion q;
      q.setRPY(0, 0, headings[k]);
      pose.pose.orientation = tf2::toMsg(q);
    } else {
      pose.pose.orientation = goal.pose.orientation;  // exactly the goal's, not via the yaw
    }
    path.poses.push_back(pose);
  }
  return path;
}

visualization_msgs::MarkerArray islandMarkers(const eaci::CellPath& islands, const TfMapFrame& frame,
                                              const ros::Time& stamp) {
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame.frame_id;
  marker.header.stamp = stamp;
  marker.ns = "islands";
  marker.id = 0;
  marker.pose.orientation.w = 1.0;
  if (islands.empty()) {
    marker.action = visualization_msgs::Marker::DELETE;
  } else {
    marker.type = visualization_msgs::Marker::SPHERE_LIST;
    marker.action = visualization_msgs::Marker::ADD;
    marker.scale.x = marker.scale.y = marker.scale.z = 2.0 * frame.resolution;
    marker.color.r = 1.0f;
    marker.color.g = 0.55f;
    marker.color.a = 1.0f;
    for (const eaci::Cell& c : islands) {
      const Eigen::Vector2d p = frame.cellToWorld(c);
      geometry_msgs::Point point;
      point.x = p.x();
      point.y = p.y();
      marker.points.push_back(point);
    }
  }
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(marker);
  return markers;
}

nav_msgs::OccupancyGrid fieldToGrid(const std::vector<double>& field, const TfMapFrame& frame, const ros::Time& stamp) {
  nav_msgs::OccupancyGrid grid;
  grid.header.frame_id = frame.frame_id;
  grid.header.stamp = stamp;
  grid.info.resolution = static_cast<float>(frame.resolution);
  grid.info.width = static_cast<std::uint32_t>(frame.width);
  grid.info.height = static_cast<std::uint32_t>(frame.height);
  grid.info.origin.position.x = frame.origin.x();
  grid.info.origin.position.y = frame.origin.y();
  grid.info.origin.orientation.w = 1.0;
  grid.data.assign(field.size(), 0);
  double low = std::numeric_limits<double>::infinity(), high = 0.0;
  for (double v : field)
    if (v > 0) low = std::min(low, v), high = std::max(high, v);
  if (!(high > low)) return grid;
  const double span = std::log(high / low);
  for (int row = 0; row < frame.height; ++row) {
    for (int col = 0; col < frame.width; ++col) {
      const double v = field[static_cast<std::size_t>(row) * frame.width + col];
      const std::size_t out = static_cast<std::size_t>(frame.height - 1 - row) * frame.width + col;  // bottom row first
      grid.data[out] = v > 0 ? static_cast<std::int8_t>(std::lround(100.0 * std::log(v / low) / span)) : 0;
    }
  }
  return grid;
}

}  // namespace eaci_ros
