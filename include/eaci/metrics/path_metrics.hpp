// Path metrics: the paper's route length and total corner angle, and a route's clearance
// from obstacles and mean cell cost.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/moves.hpp"
#include "eaci/grid/path_length.hpp"

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
//
// Exact Euclidean distances in O(width x height), however far the obstacles are (a search
// outward from each route cell costs the square of the clearance per cell): per column the
// distance to the nearest obstacle in that column, then, on the rows the route visits, the
// lower envelope of the parabolas (x - q)^2 + column_distance(q)^2 (Felzenszwalb and
// Huttenlocher, "Distance Transforms of Sampled Functions", 2012).
inline double minClearance(const CostGrid& grid, const CellPath& route) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const int w = grid.width(), h = grid.height();
  std::vector<bool> route_row(static_cast<std::size_t>(std::max(h, 0)), false);
  for (const Cell& cell : route)
    if (grid.contains(cell)) route_row[static_cast<std::size_t>(cell.row)] = true;

  // Squared distance to the nearest obstacle in the same column, +infinity if none.
  std::vector<double> column(grid.cellCount(), kInfinity);
  auto at = [w](int row, int col) {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(w) + static_cast<std::size_t>(col);
  };
  auto square = [](int v) { return static_cast<double>(v) * static_cast<double>(v); };
  for (int c = 0; c < w; ++c) {
    double distance = kInfinity;
    for (int r = 0; r < h; ++r) {
      distance = grid.isBlocked(Cell{r, c}) ? 0.0 : distance + 1.0;
      column[at(r, c)] = distance;
    }
    distance = kInfinity;
    for (int r = h - 1; r >= 0; --r) {
      distance = grid.isBlocked(Cell{r, c}) ? 0.0 : distance + 1.0;
      column[at(r, c)] = std::min(column[at(r, c)], distance);
    }
    for (int r = 0; r < h; ++r) column[at(r, c)] *= column[at(r, c)];
  }

  // Per route row: squared distance to the nearest obstacle anywhere, from the lower envelope
  // of the parabolas of the columns that have an obstacle.
  std::vector<double> squared(static_cast<std::size_t>(std::max(w, 0)));
  std::vector<int> apex(static_cast<std::size_t>(std::max(w, 0)));           // envelope parabolas' columns
  std::vector<double> from(static_cast<std::size_t>(std::max(w, 0)) + 1);   // where each takes over
  double best = kInfinity;
  for (int r = 0; r < h; ++r) {
    if (!route_row[static_cast<std::size_t>(r)]) continue;
    const double* f = &column[at(r, 0)];
    int k = -1;
    for (int q = 0; q < w; ++q) {
      if (!std::isfinite(f[q])) continue;
      double s = -kInfinity;
      while (k >= 0) {
        const int p = apex[static_cast<std::size_t>(k)];
        s = ((f[q] + square(q)) - (f[p] + square(p))) / (2.0 * (q - p));
        if (s <= from[static_cast<std::size_t>(k)]) --k;
        else break;
      }
      if (k < 0) s = -kInfinity;
      ++k;
      apex[static_cast<std::size_t>(k)] = q;
      from[static_cast<std::size_t>(k)] = s;
      from[static_cast<std::size_t>(k) + 1] = kInfinity;
    }
    for (int x = 0, j = 0; x < w; ++x) {
      if (k < 0) {
        squared[static_cast<std::size_t>(x)] = kInfinity;
        continue;
      }
      while (from[static_cast<std::size_t>(j) + 1] < x) ++j;
      const int q = apex[static_cast<std::size_t>(j)];
      squared[static_cast<std::size_t>(x)] = square(x - q) + f[q];
    }
    for (const Cell& cell : route)
      if (cell.row == r && grid.contains(cell)) best = std::min(best, squared[static_cast<std::size_t>(cell.col)]);
  }
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
