// The one place that knows both worlds: ROS messages <-> the core's grid view, cells and paths.
#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/inflation.hpp"
#include "eaci/grid/map_frame.hpp"
#include "eaci/io/occupancy_map.hpp"
#include "eaci/path/orientation.hpp"

namespace eaci_ros {

// Where a grid sits in the world (eaci::MapFrame: worldToCell, cellToWorld) and, added here,
// the TF frame it sits in. Like costmap_2d and nav_msgs/OccupancyGrid, the origin is the corner
// of the cell in the first buffer row (the bottom row) and first column, and its rotation is
// ignored.
struct TfMapFrame : eaci::MapFrame {
  std::string frame_id;
};

TfMapFrame frameOf(const nav_msgs::OccupancyGrid& grid);

// A map loaded by the core (row 0 = top) as the message map_server would publish (bottom row first).
// Throws std::invalid_argument for a map of costmap costs (mode: raw): its bytes are no occupancies.
nav_msgs::OccupancyGrid toOccupancyGrid(const eaci::OccupancyMap& map, const std::string& frame_id);

// The grid's data viewed without a copy: int8 -1 (unknown) reads as the byte 255; cells at
// or above `occupied_threshold` (0..100) are obstacles; unknown cells are obstacles, or with
// `allow_unknown` passable at the dearest cost (eaci::UnknownPolicy::kExpensive).
eaci::GridView viewOf(const nav_msgs::OccupancyGrid& grid, int occupied_threshold, bool allow_unknown);

// Marks every cell whose centre lies within `radius` metres of an occupied cell's centre as
// occupied (100), so a robot of that radius, planned as a point, keeps clear of obstacles
// (the core's exact distance transform, eaci/grid/distance_transform.hpp).
void inflateObstacles(nav_msgs::OccupancyGrid& grid, double radius, int occupied_threshold);

// The grid as costmap_2d's inflation layer would cost it (eaci/grid/inflation.hpp): occupied
// cells (at or above `occupied_threshold`) 254, unknown 255, cells within the inscribed radius
// 253, then the exponential decay out to the inflation radius. Row 0 = top.
std::vector<std::uint8_t> inflatedCostsOf(const nav_msgs::OccupancyGrid& grid, int occupied_threshold,
                                          const eaci::InflationParameters& inflation);

// The poses a plan sends (PlanReply::poses: positions in the map frame, checked by the planning
// service) as a nav_msgs/Path in `frame_id`: headings as global_planner's orientation_mode sets
// them (default forward: each pose faces the next one), the last pose with the goal's
// orientation exactly.
nav_msgs::Path toPath(const std::vector<Eigen::Vector2d>& points, const std::string& frame_id,
                      const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                      const ros::Time& stamp, eaci::OrientationMode orientation = eaci::OrientationMode::kForward);

// EACI's islands (PlanResult::islands) for RViz: one sphere list in `frame`, a sphere of two
// cells at each island's centre, in route order; empty islands: a marker that deletes the last.
visualization_msgs::MarkerArray islandMarkers(const eaci::CellPath& islands, const TfMapFrame& frame,
                                              const ros::Time& stamp);

// A per-cell field (row-major, row 0 = top) as an OccupancyGrid for RViz: log-scaled to 0..100.
nav_msgs::OccupancyGrid fieldToGrid(const std::vector<double>& field, const TfMapFrame& frame, const ros::Time& stamp);

}  // namespace eaci_ros
