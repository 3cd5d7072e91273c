// Checks a nav_msgs/Path from the planner node from first principles, against the map file the
// node loaded: shared by the ROS integration tests.
#pragma once

#include <nav_msgs/Path.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "eaci/io/occupancy_map.hpp"

namespace eaci_test {

// "" when `path` is a route from `start` to `goal` on `map`, else what is wrong with it.
// Every pose lies on a free cell, the first in the start cell, the last in the goal cell,
// consecutive poses at most one cell apart (as navfn's and global_planner's), and the segment
// between them, sampled every 1/100 of a cell, only on free cells.
inline std::string routeDefect(const eaci::OccupancyMap& map, const nav_msgs::Path& path, eaci::Cell start, eaci::Cell goal) {
  auto free = [&](eaci::Cell c) {
    return c.row >= 0 && c.col >= 0 && c.row < map.height && c.col < map.width &&
           map.cells[static_cast<std::size_t>(c.row) * map.width + c.col] == eaci::kFreeValue;
  };
  std::ostringstream defect;
  if (path.header.frame_id != "map") return "frame '" + path.header.frame_id + "'";
  eaci::Cell previous{};
  for (std::size_t k = 0; k < path.poses.size(); ++k) {
    const auto& p = path.poses[k].pose.position;
    const auto cell = map.worldToCell({p.x, p.y});
    if (!cell) return "pose " + std::to_string(k) + " is off the map";
    if (!free(*cell)) {
      defect << "pose " << k << " (row " << cell->row << ", col " << cell->col << ") is not on a free cell";
      return defect.str();
    }
    if (k == 0 && !(*cell == start)) return "the first pose is not in the start cell";
    if (k > 0) {
      const auto& q = path.poses[k - 1].pose.position;
      const double length = std::hypot(p.x - q.x, p.y - q.y);
      if (length > map.resolution * (1 + 1e-6))  // the message's resolution is a float
        return "poses " + std::to_string(k - 1) + " and " + std::to_string(k) + " are more than a cell apart";
      const int samples = std::max(1, static_cast<int>(std::ceil(length / map.resolution * 100)));
      for (int i = 1; i < samples; ++i) {
        const double t = static_cast<double>(i) / samples;
        const auto on = map.worldToCell({q.x + t * (p.x - q.x), q.y + t * (p.y - q.y)});
        if (!on || !free(*on)) return "the step to pose " + std::to_string(k) + " crosses a blocked cell";
      }
    }
    previous = *cell;
  }
  if (!path.poses.empty() && !(previous == goal)) return "the last pose is not in the goal cell";
  return "";
}

}  // namespace eaci_test
