// Exact shortest paths on the same grid and move rule as the ants: A* and a Dijkstra distance field.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

#include "eaci/grid/binary_grid.hpp"

namespace eaci {

struct ShortestPath {
  bool found = false;
  double length = std::numeric_limits<double>::infinity();  // cells
  CellPath path;                                            // start first, goal last
};

// Octile distance: the length of the shortest 8-connected path on an empty grid, a
// consistent A* heuristic under both corner rules.
inline double octileDistance(Cell a, Cell b) {
  const int dr = std::abs(a.row - b.row), dc = std::abs(a.col - b.col);
  return (kSqrt2 - 1.0) * std::min(dr, dc) + std::max(dr, dc);
}

namespace detail {
struct QueueEntry {
  double priority;
  double cost;
  std::uint32_t cell;
  // Min-heap on priority; among equals prefer the larger cost (deeper node), then the lower index.
  bool operator>(const QueueEntry& o) const {
    if (priority != o.priority) return priority > o.priority;
    if (cost != o.cost) return cost < o.cost;
    return cell > o.cell;
  }
};
}  // namespace detail

// A* from start to goal. Returns found = false when the goal is unreachable or either
// cell is off the map or blocked.
inline ShortestPath shortestPath(const BinaryGrid& grid, Cell start, Cell goal) {
  ShortestPath result;
  if (!grid.isFree(start) || !grid.isFree(goal)) return result;
  const double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(grid.cellCount(), kInf);
  std::vector<std::uint8_t> came_dir(grid.cellCount(), 0xFF);
  std::vector<std::uint8_t> closed(grid.cellCount(), 0);
  std::priority_queue<detail::QueueEntry, std::vector<detail::QueueEntry>, std::greater<detail::QueueEntry>> open;
  const auto start_index = static_cast<std::uint32_t>(grid.index(start));
  const auto goal_index = static_cast<std::uint32_t>(grid.index(goal));
  cost[start_index] = 0.0;
  open.push({octileDistance(start, goal), 0.0, start_index});
  while (!open.empty()) {
    const detail::QueueEntry top = open.top();
    open.pop();
    if (closed[top.cell]) continue;
    closed[top.cell] = 1;
    if (top.cell == goal_index) break;
    const Cell here = grid.cellAt(top.cell);
    for (int d = 0; d < kDirections; ++d) {
      if (!grid.canMove(here, d)) continue;
      const Cell next = step(here, d);
      const auto j = static_cast<std::uint32_t>(grid.index(next));
      const double g = cost[top.cell] + stepLength(d);
      if (closed[j] || g >= cost[j]) continue;
      cost[j] = g;
      came_dir[j] = static_cast<std::uint8_t>(d);
      open.push({g + octileDistance(next, goal), g, j});
    }
  }
  if (!closed[goal_index]) return result;
  result.found = true;
  result.length = cost[goal_index];
  for (Cell c = goal;;) {
    result.path.push_back(c);
    if (c == start) break;
    const int d = came_dir[grid.index(c)];
    c = Cell{c.row - kDirRow[d], c.col - kDirCol[d]};
  }
  std::reverse(result.path.begin(), result.path.end());
  return result;
}

// Dijkstra: grid distance (cells) from `source` to every cell, +infinity where unreachable.
// The move rule is symmetric, so this is also the distance from every cell to `source`.
inline std::vector<double> distanceField(const BinaryGrid& grid, Cell source) {
  const double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(grid.cellCount(), kInf);
  if (!grid.isFree(source)) return dist;
  std::priority_queue<detail::QueueEntry, std::vector<detail::QueueEntry>, std::greater<detail::QueueEntry>> open;
  const auto s = static_cast<std::uint32_t>(grid.index(source));
  dist[s] = 0.0;
  open.push({0.0, 0.0, s});
  while (!open.empty()) {
    const detail::QueueEntry top = open.top();
    open.pop();
    if (top.cost > dist[top.cell]) continue;
    const Cell here = grid.cellAt(top.cell);
    for (int d = 0; d < kDirections; ++d) {
      if (!grid.canMove(here, d)) continue;
      const auto j = static_cast<std::uint32_t>(grid.index(step(here, d)));
      const double g = top.cost + stepLength(d);
      if (g >= dist[j]) continue;
      dist[j] = g;
      open.push({g, g, j});
    }
  }
  return dist;
}

}  // namespace eaci
