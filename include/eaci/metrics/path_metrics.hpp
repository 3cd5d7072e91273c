// Path metrics: the paper's total corner angle, and a route's clearance from obstacles and
// mean cell cost. Its length (Tables 1-3) is pathLength, grid/moves.hpp.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_point.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/distance_transform.hpp"
#include "eaci/grid/line_clearance.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// The move from cell a to cell b as a vector in cell units: x columns right, y rows down.
inline Eigen::Vector2d moveVector(Cell a, Cell b) {
  return {static_cast<double>(b.col - a.col), static_cast<double>(b.row - a.row)};
}

// Sum of the turning angles at the path's inner cells, degrees (multiples of 45 on an
// 8-connected path; other steps count the angle between their straight lines).
inline double totalTurnDegrees(const CellPath& path) {
  constexpr double kDegreesPerRadian = 57.295779513082320876798;
  double total = 0.0;
  for (std::size_t k = 2; k < path.size(); ++k) {
    const Eigen::Vector2d in = moveVector(path[k - 2], path[k - 1]);
    const Eigen::Vector2d out = moveVector(path[k - 1], path[k]);
    const double a = std::atan2(in.y(), in.x());
    const double b = std::atan2(out.y(), out.x());
    double turn = std::abs(b - a) * kDegreesPerRadian;
    if (turn > 180.0) turn = 360.0 - turn;
    total += turn;
  }
  return std::round(total * 1e9) / 1e9;
}

// 1 for each obstacle cell of the grid, 0 elsewhere (row-major), for the distance transform.
inline std::vector<std::uint8_t> obstacleCells(const CostGrid& grid) {
  std::vector<std::uint8_t> obstacle(grid.cellCount());
  const std::uint8_t* cells = grid.cellBytes();
  for (std::size_t i = 0; i < obstacle.size(); ++i) obstacle[i] = cells[i] == CostGrid::kObstacle ? 1 : 0;
  return obstacle;
}

// The obstacle cells and the squared distance transform from them, made once for both
// clearance measures below (an O(width x height) pass each).
struct ObstacleDistances {
  std::vector<std::uint8_t> obstacle;  // obstacleCells
  std::vector<double> squared;         // squaredDistancesToSources
};
inline ObstacleDistances obstacleTransform(const CostGrid& grid) {
  ObstacleDistances d{obstacleCells(grid), {}};
  d.squared = squaredDistancesToSources(grid.width(), grid.height(), d.obstacle);
  return d;
}

// The smallest distance, in cells, from the centre of a route cell to the centre of the
// nearest obstacle cell (times the resolution: metres). A diagonal neighbour of an obstacle has
// clearance sqrt 2, a cell two columns beside a wall 2, a blocked route cell 0. Cells beyond the
// map's border are not obstacles (the map says nothing about them). +infinity when the route
// is empty or the grid has no obstacle; route cells off the grid are skipped.
// Exact Euclidean distances in O(width x height) (squaredDistancesToSources,
// grid/distance_transform.hpp), however far the obstacles are.
inline double minClearance(const CostGrid& grid, const CellPath& route, const ObstacleDistances& distances) {
  const std::vector<double>& squared = distances.squared;
  double best = std::numeric_limits<double>::infinity();
  for (const Cell& cell : route)
    if (grid.contains(cell)) best = std::min(best, squared[grid.index(cell)]);
  return std::sqrt(best);
}
inline double minClearance(const CostGrid& grid, const CellPath& route) {
  return minClearance(grid, route, obstacleTransform(grid));
}

// The smallest distance, in cells, from the polyline through `corners` (the smoothed route, its
// straight segments between cell centres: where the robot drives) to the centre of the nearest
// obstacle cell; minClearance's measure, but along the lines and not only at cell centres (a
// line between two cells may pass nearer a wall than either centre). Exact: the lines are cut
// into pieces of at most 4 cells, and each piece looks for obstacles (segmentClearanceWithin,
// grid/line_clearance.hpp) no farther than its start's clearance (from the distance transform,
// plus 0.71 for a start off its cell's centre) or the best so far. +infinity without obstacles
// or corners; segments with a corner off the grid are skipped. The corners may lie off the cell
// centres (CellPolyline, grid/cell_point.hpp).
inline double minPolylineClearance(const CostGrid& grid, const CellPolyline& corners,
                                   const ObstacleDistances& distances) {
  const std::vector<double>& squared = distances.squared;
  const auto distanceAt = [&](const Eigen::Vector2d& p) {  // from p's cell's centre
    const Cell c = cellOfPoint(p);
    return grid.contains(c) ? std::sqrt(squared[grid.index(c)]) : std::numeric_limits<double>::infinity();
  };
  // A first bound for the lines: each corner is at most its cell's clearance + 0.71 from an obstacle.
  double best = std::numeric_limits<double>::infinity();
  for (const CellPoint& corner : corners) best = std::min(best, distanceAt(corner) + 0.71);
  for (std::size_t k = 0; k < corners.size(); ++k) {  // k = 0: the first corner alone
    const Eigen::Vector2d a = corners[k > 0 ? k - 1 : 0], b = corners[k];
    if (!grid.contains(cellOfPoint(a)) || !grid.contains(cellOfPoint(b))) continue;
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 4.0)));
    for (int i = 0; i < pieces; ++i) {
      const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(i) / pieces);
      const Eigen::Vector2d q = a + (b - a) * (static_cast<double>(i + 1) / pieces);
      const double reach = std::min(distanceAt(p) + 0.71, best) + 1e-9;  // the piece's nearest obstacle is within it
      if (std::isfinite(reach)) best = std::min(best, segmentClearanceWithin(grid, p, q, reach));
    }
  }
  return best;
}
inline double minPolylineClearance(const CostGrid& grid, const CellPath& corners, const ObstacleDistances& distances) {
  return minPolylineClearance(grid, cellPolyline(corners), distances);
}
inline double minPolylineClearance(const CostGrid& grid, const CellPath& corners) {
  return minPolylineClearance(grid, corners, obstacleTransform(grid));
}

// The mean cost 0..254 (CostGrid::cost) of the route's cells. NaN when the route is empty or
// has a cell that is off the grid or blocked (not a route).
inline double meanCellCost(const CostGrid& grid, const CellPath& route) {
  if (route.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (const Cell& cell : route) {
    if (!grid.isFree(cell)) return std::numeric_limits<double>::quiet_NaN();
    sum += grid.cost(cell);
  }
  return sum / static_cast<double>(route.size());
}

}  // namespace eaci
