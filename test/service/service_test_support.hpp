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

// "" when the poses (metres) run from `start` to `goal`, lie at most `spacing` metres apart,
// and every segment between two of them, sampled every 1/100 of a cell, stays in cells below
// 253 (`start_cells` may hold the robot in the band); else the first fault. A check apart from
// the service's own segment walk: dense samples, not border crossings.
inline std::string sentPosesFault(const CostmapSnapshot& costmap, const std::vector<Eigen::Vector2d>& poses,
                               const Eigen::Vector2d& start, const Eigen::Vector2d& goal, double spacing) {
  if (poses.size() < 2) return "fewer than two poses";
  if ((poses.front() - start).norm() > 1e-9) return "the first pose is not the start";
  if ((poses.back() - goal).norm() > 1e-9) return "the last pose is not the goal";
  const eaci::MapFrame& frame = costmap.frame;
  const eaci::Cell start_cell = *frame.worldToCell(start);
  for (std::size_t k = 1; k < poses.size(); ++k) {
    const Eigen::Vector2d a = poses[k - 1], b = poses[k];
    if ((b - a).norm() > spacing + 1e-9) return "poses " + std::to_string(k - 1) + " and " + std::to_string(k) + " are too far apart";
    const int samples = std::max(1, static_cast<int>(std::ceil((b - a).norm() / frame.resolution * 100)));
    for (int i = 0; i <= samples; ++i) {
      const auto cell = frame.worldToCell(a + (b - a) * (static_cast<double>(i) / samples));
      if (!cell) return "segment " + std::to_string(k) + " leaves the map";
      if (at(costmap, cell->row, cell->col) >= kCostmapInscribed && !(*cell == start_cell))
        return "segment " + std::to_string(k) + " enters the blocked cell (row " + std::to_string(cell->row) +
               ", col " + std::to_string(cell->col) + ")";
    }
  }
  return "";
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
