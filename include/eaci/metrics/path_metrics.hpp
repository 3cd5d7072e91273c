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
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/distance_transform.hpp"
#include "eaci/grid/moves.hpp"
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

// The smallest distance, in cells, from the centre of a route cell to the centre of the
// nearest obstacle cell (times the resolution: metres). A diagonal neighbour of an obstacle has
// clearance sqrt 2, a cell two columns beside a wall 2, a blocked route cell 0. Cells beyond the
// map's border are not obstacles (the map says nothing about them). +infinity when the route
// is empty or the grid has no obstacle; route cells off the grid are skipped.
// Exact Euclidean distances in O(width x height) (squaredDistancesToSources,
// grid/distance_transform.hpp), however far the obstacles are.
inline double minClearance(const CostGrid& grid, const CellPath& route) {
  std::vector<std::uint8_t> obstacle(grid.cellCount());
  const std::uint8_t* cells = grid.cellBytes();
  for (std::size_t i = 0; i < obstacle.size(); ++i) obstacle[i] = cells[i] == CostGrid::kObstacle ? 1 : 0;
  const std::vector<double> squared = squaredDistancesToSources(grid.width(), grid.height(), obstacle);
  double best = std::numeric_limits<double>::infinity();
  for (const Cell& cell : route)
    if (grid.contains(cell)) best = std::min(best, squared[grid.index(cell)]);
  return std::sqrt(best);
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
