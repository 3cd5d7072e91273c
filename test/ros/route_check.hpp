// Checks a nav_msgs/Path from the planner node from first principles, against the map file the
// node loaded: shared by the ROS integration tests.
#pragma once

#include <nav_msgs/Path.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "eaci/io/occupancy_map.hpp"

namespace eaci_test {

// "" when `path` is a route from `start` to `goal` on `map`, else what is wrong with it.
// Every pose lies on a free cell, the first in the start cell, the last in the goal cell, and
// consecutive poses lie in the same or 8-neighbouring cells, a diagonal step only between two
// free side cells (the node never cuts corners).
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
      const int dr = cell->row - previous.row, dc = cell->col - previous.col;
      if (std::abs(dr) > 1 || std::abs(dc) > 1) return "poses " + std::to_string(k - 1) + " and " + std::to_string(k) + " are not in neighbouring cells";
      if (dr != 0 && dc != 0 && (!free({previous.row + dr, previous.col}) || !free({previous.row, previous.col + dc})))
        return "the step to pose " + std::to_string(k) + " cuts a corner";
    }
    previous = *cell;
  }
  if (!path.poses.empty() && !(previous == goal)) return "the last pose is not in the goal cell";
  return "";
}

}  // namespace eaci_test
