// Path metrics: the paper's route length and total corner angle, and a route's clearance
// from obstacles and mean cell cost.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <algorithm>
#include <cstddef>
#include <limits>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// The move from cell a to cell b as a vector in cell units: x columns right, y rows down.
inline Eigen::Vector2d moveVector(Cell a, Cell b) {
  return {static_cast<double>(b.col - a.col), static_cast<double>(b.row - a.row)};
}

// Length in cells: straight step 1, diagonal sqrt 2 (a jump between cells that are not
// neighbours, which no planner returns, counts its straight-line length).
inline double pathLength(const CellPath& path) {
  double length = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const int dir = directionBetween(path[k - 1], path[k]);
    if (dir >= 0) {
      length += stepLength(dir);
    } else {
      const Eigen::Vector2d move = moveVector(path[k - 1], path[k]);
      length += std::hypot(move.x(), move.y());
    }
  }
  return length;
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
//
// Per route cell the search goes outward ring by ring (Chebyshev distance r = 1, 2, ...): an
// obstacle on ring r is at least r away, so the search stops at the first ring that cannot
// beat the best distance found so far, this cell's or the route's.
inline double minClearance(const CostGrid& grid, const CellPath& route) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  bool any_obstacle = false;
  for (std::size_t i = 0; i < grid.cellCount() && !any_obstacle; ++i) any_obstacle = grid.isBlocked(grid.cellAt(i));
  if (!any_obstacle) return kInfinity;

  double best = kInfinity;  // over the route so far
  for (const Cell& cell : route) {
    if (!grid.contains(cell)) continue;
    if (grid.isBlocked(cell)) return 0.0;
    // The farthest ring that still touches the map.
    const int last_ring = std::max({cell.row, grid.height() - 1 - cell.row, cell.col, grid.width() - 1 - cell.col});
    auto consider = [&](int row, int col) {
      const Cell other{row, col};
      if (!grid.contains(other) || !grid.isBlocked(other)) return;
      best = std::min(best, std::hypot(static_cast<double>(row - cell.row), static_cast<double>(col - cell.col)));
    };
    for (int r = 1; r <= last_ring && r < best; ++r) {
      for (int dc = -r; dc <= r; ++dc) consider(cell.row - r, cell.col + dc), consider(cell.row + r, cell.col + dc);
      for (int dr = -r + 1; dr <= r - 1; ++dr) consider(cell.row + dr, cell.col - r), consider(cell.row + dr, cell.col + r);
    }
  }
  return best;
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
