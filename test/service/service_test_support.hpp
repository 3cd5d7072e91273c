// Costmaps and checks for the planning service's tests, written from first principles (not
// with the planner's own code).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "planning_service.hpp"

namespace eaci_service::test {

// A costmap of `width` x `height` free cells of 1 m, origin (0, 0), top row first in the buffer.
inline CostmapSnapshot openCostmap(int width, int height) {
  CostmapSnapshot costmap;
  costmap.frame.width = width;
  costmap.frame.height = height;
  costmap.frame.resolution = 1.0;
  costmap.frame_id = "map";
  costmap.order = eaci::RowOrder::kTopFirst;
  costmap.cells.assign(static_cast<std::size_t>(width) * height, kCostmapFree);
  return costmap;
}

inline std::uint8_t& at(CostmapSnapshot& costmap, int row, int col) {
  return costmap.cells[static_cast<std::size_t>(row) * costmap.frame.width + col];
}
inline std::uint8_t at(const CostmapSnapshot& costmap, int row, int col) {
  return costmap.cells[static_cast<std::size_t>(row) * costmap.frame.width + col];
}

// The centre of cell (row, col) in metres (row 0 = top: y = height - row - 0.5).
inline Eigen::Vector2d centre(const CostmapSnapshot& costmap, int row, int col) {
  return {col + 0.5, costmap.frame.height - row - 0.5};
}

inline PlanRequest request(const CostmapSnapshot& costmap, eaci::Cell from, eaci::Cell to, double tolerance = -1) {
  PlanRequest r;
  r.start = centre(costmap, from.row, from.col);
  r.goal = centre(costmap, to.row, to.col);
  r.tolerance = tolerance;
  return r;
}

// "" when `path` runs from `from` to `to` by 8-neighbour moves over cells below 253 (the first
// `band_cells` cells may be in the inscribed band: the robot stood there), never between two
// corner-touching blocked cells; else what is wrong.
inline std::string routeDefect(const CostmapSnapshot& costmap, const eaci::CellPath& path, eaci::Cell from,
                               eaci::Cell to, int band_cells = 0) {
  if (path.empty()) return "empty route";
  if (!(path.front() == from)) return "does not start at the start";
  if (!(path.back() == to)) return "does not end at the goal";
  const auto blocked = [&](int row, int col) {
    return row < 0 || col < 0 || row >= costmap.frame.height || col >= costmap.frame.width ||
           at(costmap, row, col) >= kCostmapInscribed;
  };
  for (std::size_t i = 0; i < path.size(); ++i) {
    const eaci::Cell c = path[i];
    if (blocked(c.row, c.col) && !(static_cast<int>(i) < band_cells && at(costmap, c.row, c.col) != kCostmapLethal))
      return "cell " + std::to_string(i) + " is an obstacle";
    if (i == 0) continue;
    const int dr = c.row - path[i - 1].row, dc = c.col - path[i - 1].col;
    if (std::abs(dr) > 1 || std::abs(dc) > 1 || (dr == 0 && dc == 0)) return "a jump at cell " + std::to_string(i);
    if (dr != 0 && dc != 0 && (blocked(path[i - 1].row + dr, path[i - 1].col) || blocked(path[i - 1].row, path[i - 1].col + dc)) &&
        static_cast<int>(i) > band_cells)
      return "a corner cut at cell " + std::to_string(i);
  }
  return "";
}

// The planner's robot-ready defaults with a fixed seed and one thread unless asked.
inline PlanningService::Configuration configuration(eaci::Algorithm algorithm = eaci::Algorithm::kEaci) {
  PlanningService::Configuration config;
  config.params = rosDefaultParameters();
  config.options.algorithm = algorithm;
  config.options.landmarks = 0;
  return config;
}

inline void configure(PlanningService& service, const PlanningService::Configuration& config) {
  service.configure(config.params, config.options, config.error);
}

}  // namespace eaci_service::test
