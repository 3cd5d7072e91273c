// What `eaci_bench costs` measures on a route over a costmap_2d-style cost map, and its
// references: the route the robot would drive (the grid route, or the smoothed route's straight
// segments), its cost, length, turning, clearance, mean cell cost and the lethal / inscribed
// cells it enters; a weighted Dijkstra written from first principles (the independent check of
// A*'s cost). Header-only on the core alone, so that
// test/test_bench_cost_checks.cpp can check it by hand.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/inflation.hpp"
#include "eaci/grid/moves.hpp"
#include "eaci/metrics/path_metrics.hpp"
#include "eaci/path/smoothing.hpp"

namespace eaci_bench {

// A costmap_2d char map as inflatedCosts() returns it: row-major, row 0 = top.
struct CostBytes {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> bytes;

  bool contains(eaci::Cell c) const { return c.row >= 0 && c.col >= 0 && c.row < height && c.col < width; }
  std::uint8_t at(eaci::Cell c) const {
    return bytes[static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c.col)];
  }
};

// The cells a route passes through when it is driven: consecutive corners joined by straight
// segments between cell centres (an 8-connected route's segments are its own moves). Each cell
// once per segment, in order; cells a segment only touches at a corner are included when
// `with_touched` (the smoother keeps those free too, and a robot passing a corner is that near).
inline eaci::CellPath drivenCells(const eaci::CellPath& corners, bool with_touched) {
  eaci::CellPath cells;
  if (corners.empty()) return cells;
  cells.push_back(corners.front());
  for (std::size_t k = 1; k < corners.size(); ++k) {
    bool first = true;
    eaci::traverseSegment(corners[k - 1], corners[k], [&](eaci::Cell c, double length) {
      if (first) {  // the segment's first cell is the previous corner, already listed
        first = false;
        return true;
      }
      if (length > 0 || with_touched) cells.push_back(c);
      return true;
    });
  }
  return cells;
}

// The cost of driving the corners' segments: a segment between 8-neighbours costs its move
// (CostGrid::moveCost, as the planners count it), a longer one the cost of the cells it crosses
// (segmentCost, as the smoother counts it when it replaces a stretch of route). So the driven
// cost of a grid route is its PlanResult::cost, and smoothing never raises it.
inline double drivenCost(const eaci::CostGrid& grid, const eaci::CellPath& corners) {
  double cost = 0.0;
  for (std::size_t k = 1; k < corners.size(); ++k) {
    const int dir = eaci::directionBetween(corners[k - 1], corners[k]);
    if (dir >= 0) {
      if (!grid.canMove(corners[k - 1], dir)) return std::numeric_limits<double>::infinity();
      cost += grid.moveCost(corners[k - 1], dir);
    } else {
      cost += eaci::segmentCost(grid, corners[k - 1], corners[k]);
    }
  }
  return cost;
}

struct RouteCheck {
  double cost = std::numeric_limits<double>::infinity();  // drivenCost on the planning grid
  double length = std::numeric_limits<double>::infinity();  // cells, along the corners
  double turn_deg = 0.0;                                   // total turning at the corners
  double min_clearance = std::numeric_limits<double>::infinity();  // cells, driven cells to the map's obstacles
  double mean_cell_cost = std::numeric_limits<double>::quiet_NaN();  // 0..252, over the cells it crosses
  int lethal_cells = 0;     // driven cells, corner-touched ones included, of cost 254 (an obstacle) or 255 (unknown)
  int inscribed_cells = 0;  // ... of cost 253 (within the inscribed radius of an obstacle)
};

// `planning`: the grid the planners searched (inflated costs, >= 253 blocked); `obstacles`: the
// map's own obstacles (the distances of the clearance); `costs`: the inflated char map.
inline RouteCheck checkRoute(const eaci::CostGrid& planning, const eaci::CostGrid& obstacles, const CostBytes& costs,
                             const eaci::CellPath& corners) {
  RouteCheck check;
  if (corners.empty()) return check;
  check.cost = drivenCost(planning, corners);
  check.length = eaci::pathLength(corners);
  check.turn_deg = eaci::totalTurnDegrees(corners);
  const eaci::CellPath crossed = drivenCells(corners, false);
  check.min_clearance = eaci::minClearance(obstacles, crossed);
  double sum = 0.0;
  for (const eaci::Cell& c : crossed) sum += costs.contains(c) ? costs.at(c) : eaci::kCostmapUnknown;
  check.mean_cell_cost = sum / static_cast<double>(crossed.size());
  for (const eaci::Cell& c : drivenCells(corners, true)) {
    const std::uint8_t v = costs.contains(c) ? costs.at(c) : eaci::kCostmapUnknown;
    if (v >= eaci::kCostmapLethal) ++check.lethal_cells;
    else if (v == eaci::kCostmapInscribed) ++check.inscribed_cells;
  }
  return check;
}

// The cheapest route's cost by Dijkstra from first principles, independent of the core's grid
// and A*: bytes >= lethal are walls (the planners' costmap reading without unknown cells), a
// move enters a cell of byte c for step x (neutral + factor x c) / neutral, a diagonal needs
// both side cells open (corner cutting forbidden). +infinity when the goal cannot be reached.
inline double dijkstraCost(const CostBytes& map, eaci::Cell start, eaci::Cell goal, std::uint8_t lethal = 253,
                           double neutral = 50.0, double factor = 3.0) {
  const auto open = [&](int r, int c) { return r >= 0 && c >= 0 && r < map.height && c < map.width && map.at({r, c}) < lethal; };
  if (!open(start.row, start.col) || !open(goal.row, goal.col)) return std::numeric_limits<double>::infinity();
  std::vector<double> best(map.bytes.size(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  const auto index = [&](int r, int c) { return static_cast<std::size_t>(r) * static_cast<std::size_t>(map.width) + static_cast<std::size_t>(c); };
  best[index(start.row, start.col)] = 0.0;
  queue.push({0.0, index(start.row, start.col)});
  while (!queue.empty()) {
    const auto [cost, here] = queue.top();
    queue.pop();
    if (cost > best[here]) continue;
    const int r = static_cast<int>(here / static_cast<std::size_t>(map.width));
    const int c = static_cast<int>(here % static_cast<std::size_t>(map.width));
    if (r == goal.row && c == goal.col) return cost;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        if ((dr == 0 && dc == 0) || !open(r + dr, c + dc)) continue;
        const bool diagonal = dr != 0 && dc != 0;
        if (diagonal && !(open(r + dr, c) && open(r, c + dc))) continue;
        const double step = diagonal ? std::sqrt(2.0) : 1.0;
        const double next = cost + step * (neutral + factor * map.at({r + dr, c + dc})) / neutral;
        const std::size_t there = index(r + dr, c + dc);
        if (next < best[there]) {
          best[there] = next;
          queue.push({next, there});
        }
      }
  }
  return std::numeric_limits<double>::infinity();
}

// (cost / reference - 1) x 100; +infinity without a route.
inline double costGapPct(double cost, double reference) {
  if (!std::isfinite(cost) || !(reference > 0)) return std::numeric_limits<double>::infinity();
  return (cost / reference - 1.0) * 100.0;
}

}  // namespace eaci_bench
