// A drivable route from a grid route: line-of-sight shortcuts over the 8-connected cells
// (beyond the paper; off for its benchmarks). A shortcut is taken only when the straight
// segment touches no obstacle cell, corners included, costs no more than the stretch of route
// it replaces, and enters no cell costlier than the costliest cell of that stretch: the
// smoothed route is never costlier, and on a costmap never nearer the walls, than the grid
// route (on a map without costs only the first two conditions bite).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <vector>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci {

// The cells a straight segment between two cell centres passes through, each with the length
// of the segment inside it (cells it only touches at a corner come with length 0), in order.
// `visit(cell, length)` returns false to stop the walk early.
template <class Visit>
void traverseSegment(Cell from, Cell to, Visit&& visit) {
  const double dx = to.col - from.col, dy = to.row - from.row;
  const double total = std::hypot(dx, dy);
  const int step_col = dx > 0 ? 1 : -1, step_row = dy > 0 ? 1 : -1;
  // Parameter t in [0, 1] along the segment; cell borders lie half a cell from the centres.
  const double t_per_col = dx != 0 ? 1.0 / std::abs(dx) : std::numeric_limits<double>::infinity();
  const double t_per_row = dy != 0 ? 1.0 / std::abs(dy) : std::numeric_limits<double>::infinity();
  double next_col_t = 0.5 * t_per_col, next_row_t = 0.5 * t_per_row, t = 0.0;
  Cell cell = from;
  constexpr double kSame = 1e-12;
  for (;;) {
    const double exit_t = std::min({next_col_t, next_row_t, 1.0});
    if (!visit(cell, (exit_t - t) * total)) return;
    if (exit_t >= 1.0) return;
    t = exit_t;
    if (std::abs(next_col_t - next_row_t) < kSame) {  // through a corner: both side cells are touched
      if (!visit(Cell{cell.row, cell.col + step_col}, 0.0) || !visit(Cell{cell.row + step_row, cell.col}, 0.0)) return;
      cell = Cell{cell.row + step_row, cell.col + step_col};
      next_col_t += t_per_col;
      next_row_t += t_per_row;
    } else if (next_col_t < next_row_t) {
      cell.col += step_col;
      next_col_t += t_per_col;
    } else {
      cell.row += step_row;
      next_row_t += t_per_row;
    }
  }
}

// What driving a straight segment between two cell centres costs, from one walk along it.
struct SegmentCost {
  // Each cell's length inside the segment, weighted like a move into that cell
  // (CostGrid::moveCostInto per unit length); +infinity if it touches an obstacle or leaves the map.
  double cost = 0.0;
  // The highest cell cost (CostGrid::cost) among the cells it passes through or touches at a
  // corner; 255 if it touches an obstacle or leaves the map.
  int peak = 0;
};

// The segment's cost and peak. The walk ends early once the cost so far is above `cost_bound`
// or the peak above `peak_bound` (each then already above its bound, as the whole segment's
// would be: costs only add up); the defaults walk the whole segment.
inline SegmentCost segmentCostAndPeak(const CostGrid& grid, Cell from, Cell to,
                                      double cost_bound = std::numeric_limits<double>::infinity(),
                                      int peak_bound = 255) {
  SegmentCost segment;
  traverseSegment(from, to, [&](Cell c, double length) {
    if (!grid.isFree(c)) {
      segment.cost = std::numeric_limits<double>::infinity();
      segment.peak = 255;
      return false;
    }
    segment.cost += length * grid.moveCostInto(grid.index(c), 0);  // direction 0: a straight move, length 1
    segment.peak = std::max<int>(segment.peak, grid.cost(c));
    return segment.cost <= cost_bound && segment.peak <= peak_bound;
  });
  return segment;
}

// The segment's cost alone (SegmentCost::cost).
inline double segmentCost(const CostGrid& grid, Cell from, Cell to) { return segmentCostAndPeak(grid, from, to).cost; }

// Where a straight segment between two cell centres crosses each cell: the middle of its
// stretch inside every cell after `from` that it passes through (cells it only touches at a
// corner are skipped), as fractions t of the segment, ending with t = 1 at `to`. Poses there
// lie in cells that follow one another side by side, or diagonally only through a corner whose
// two side cells the segment touches.
inline std::vector<double> cellMidpointsAlong(Cell from, Cell to) {
  std::vector<double> ts;
  const double total = std::hypot(to.col - from.col, to.row - from.row);
  if (total == 0) return ts;
  double done = 0.0;
  bool first = true;
  traverseSegment(from, to, [&](Cell, double length) {
    if (length > 0) {
      if (!first) ts.push_back(std::min(1.0, (done + length / 2) / total));
      first = false;
      done += length;
    }
    return true;
  });
  if (ts.empty()) ts.push_back(1.0);
  ts.back() = 1.0;  // the last cell's pose is its centre
  return ts;
}

// Greedy string pulling: from each kept cell, the farthest later cell of the route reachable
// by an allowed shortcut (the search stops at the first that is not). Returns the kept cells,
// start and goal included; consecutive kept cells are joined by straight segments.
// A route that is not 8-connected is returned as it is. The work is up to quadratic in the
// route's length (each shortcut tried is walked cell by cell, once, until it fails): `stop` is
// ticked by the cells each try spans, and once it says stop the route is smoothed up to where
// it got and goes on cell by cell from there (as valid as the whole smoothed route).
inline CellPath smoothRoute(const CostGrid& grid, const CellPath& route, StopPoll* stop = nullptr) {
  if (route.size() < 3 || !std::isfinite(routeCost(grid, route))) return route;
  const auto moveCost = [&](std::size_t k) {  // the move into route[k]
    const int dir = directionBetween(route[k - 1], route[k]);
    return dir < 0 ? std::numeric_limits<double>::infinity() : grid.moveCost(route[k - 1], dir);
  };
  CellPath kept{route.front()};
  std::size_t i = 0;
  while (i + 1 < route.size()) {
    std::size_t best = i + 1;
    double stretch_cost = moveCost(i + 1);
    int stretch_peak = std::max<int>(grid.cost(route[i]), grid.cost(route[i + 1]));
    for (std::size_t j = i + 2; j < route.size(); ++j) {
      if (stop != nullptr && stop->tick(j - i)) {  // a walk of about j - i cells
        kept.insert(kept.end(), route.begin() + static_cast<std::ptrdiff_t>(i) + 1, route.end());
        return kept;
      }
      stretch_cost += moveCost(j);
      stretch_peak = std::max<int>(stretch_peak, grid.cost(route[j]));
      const double cost_bound = stretch_cost + 1e-9;
      const SegmentCost shortcut = segmentCostAndPeak(grid, route[i], route[j], cost_bound, stretch_peak);
      if (shortcut.cost > cost_bound || shortcut.peak > stretch_peak) break;
      best = j;
    }
    kept.push_back(route[best]);
    i = best;
  }
  return kept;
}

}  // namespace eaci
