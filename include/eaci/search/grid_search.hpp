// One search over the grid's moves, behind every exact search of the project: A*
// (shortestPath), the Dijkstra cost field (costField), the island leg fields
// (LegDistanceField) and reachability (reachableFrom). What differs between them is a
// parameter: a target to stop at (and steer towards), a window to stay in, whether to keep
// the moves for the route back, and whether distances matter at all.
//
// A route's cost is the sum of its moves' costs (CostGrid::moveCost); the "distance" a search
// finds is that cost, which on a binary map (every free cell of cost 0) is the grid distance.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <vector>

#include "eaci/grid/cost_grid.hpp"

namespace eaci {

// Octile distance: the length of the shortest 8-connected path on an empty grid, a
// consistent A* heuristic under both corner rules. No move costs less than its length (the
// cheapest cell, cost 0, weighs a move by exactly 1), so it stays consistent for route costs.
inline double octileDistance(Cell a, Cell b) {
  const int dr = std::abs(a.row - b.row), dc = std::abs(a.col - b.col);
  return (kSqrt2 - 1.0) * std::min(dr, dc) + std::max(dr, dc);
}

// A rectangle of cells, stored row-major ("slots"); the search never leaves it.
struct CellWindow {
  int row0 = 0, col0 = 0, rows = 0, cols = 0;

  static CellWindow whole(const CostGrid& grid) { return {0, 0, grid.height(), grid.width()}; }
  // The bounding box of `cells` grown by `margin`, clipped to the grid.
  static CellWindow around(const CostGrid& grid, const CellPath& cells, int margin) {
    int r0 = cells.front().row, r1 = r0, c0 = cells.front().col, c1 = c0;
    for (const Cell& c : cells) {
      r0 = std::min(r0, c.row);
      r1 = std::max(r1, c.row);
      c0 = std::min(c0, c.col);
      c1 = std::max(c1, c.col);
    }
    const int top = std::max(0, r0 - margin), left = std::max(0, c0 - margin);
    return {top, left, std::min(grid.height() - 1, r1 + margin) - top + 1,
            std::min(grid.width() - 1, c1 + margin) - left + 1};
  }

  bool contains(Cell c) const { return c.row >= row0 && c.col >= col0 && c.row < row0 + rows && c.col < col0 + cols; }
  std::size_t size() const { return static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols); }
  std::size_t slot(Cell c) const {
    return static_cast<std::size_t>(c.row - row0) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c.col - col0);
  }
  Cell cellAt(std::size_t s) const {
    return Cell{row0 + static_cast<int>(s / static_cast<std::size_t>(cols)),
                col0 + static_cast<int>(s % static_cast<std::size_t>(cols))};
  }
};

enum class SearchOrder {
  kByDistance,  // Dijkstra / A*: cells settle in order of route cost (exact costs)
  kAnyOrder,    // a flood: which cells are reachable, nothing more (distance 0 on each)
};

struct GridSearchRequest {
  Cell source;
  std::optional<Cell> target;  // stop once it is settled; A* steers towards it (octile heuristic)
  std::optional<CellWindow> window;  // default: the whole grid
  bool keep_moves = false;     // remember the move into each cell, for routeTo()
  SearchOrder order = SearchOrder::kByDistance;
  bool reverse_costs = false;  // costs of routes *to* the source (see searchGrid)
};

struct GridSearchResult {
  CellWindow window;
  std::vector<double> distance;        // per window slot: route cost from the source; +infinity = not reached
  std::vector<std::uint8_t> came_dir;  // per window slot (keep_moves): the move into it, kNoMove at the source
  double largest_distance = 0.0;       // over the settled cells
  static constexpr std::uint8_t kNoMove = 0xFF;

  double at(Cell c) const {
    return window.contains(c) ? distance[window.slot(c)] : std::numeric_limits<double>::infinity();
  }
  bool reached(Cell c) const { return std::isfinite(at(c)); }

  // The cells from the source to `c` (needs keep_moves); empty when `c` was not reached.
  CellPath routeTo(Cell c) const {
    CellPath route;
    if (!reached(c) || came_dir.empty()) return route;
    for (;;) {
      route.push_back(c);
      const std::uint8_t d = came_dir[window.slot(c)];
      if (d == kNoMove) break;
      c = Cell{c.row - kDirRow[d], c.col - kDirCol[d]};
    }
    std::reverse(route.begin(), route.end());
    return route;
  }
};

namespace detail {
struct SearchEntry {
  double priority;
  double cost;
  std::uint32_t slot;
  // Min-heap on priority; among equals prefer the larger cost (deeper node), then the lower slot.
  bool operator>(const SearchEntry& o) const {
    if (priority != o.priority) return priority > o.priority;
    if (cost != o.cost) return cost < o.cost;
    return slot > o.slot;
  }
};
}  // namespace detail

// The search itself. A blocked or off-window source reaches nothing. A move costs by the cell
// it enters, so costs from the source are not costs to it on a cost map (they are on a binary
// map): a field that must hold costs *to* its source searches the reversed moves
// (`reverse_costs`), which charge the cell a move leaves instead.
inline GridSearchResult searchGrid(const CostGrid& grid, const GridSearchRequest& request) {
  GridSearchResult result;
  result.window = request.window.value_or(CellWindow::whole(grid));
  const CellWindow& window = result.window;
  result.distance.assign(window.size(), std::numeric_limits<double>::infinity());
  if (request.keep_moves) result.came_dir.assign(window.size(), GridSearchResult::kNoMove);
  if (!grid.isFree(request.source) || !window.contains(request.source)) return result;

  const auto source = static_cast<std::uint32_t>(window.slot(request.source));
  result.distance[source] = 0.0;
  const auto estimate = [&](Cell c) { return request.target ? octileDistance(c, *request.target) : 0.0; };
  constexpr std::uint32_t kNoTarget = std::numeric_limits<std::uint32_t>::max();
  const std::uint32_t target_slot = request.target && window.contains(*request.target)
                                        ? static_cast<std::uint32_t>(window.slot(*request.target))
                                        : kNoTarget;

  if (request.order == SearchOrder::kAnyOrder) {  // a flood: depth first, each cell once
    std::vector<std::uint32_t> frontier{source};
    while (!frontier.empty()) {
      const Cell here = window.cellAt(frontier.back());
      frontier.pop_back();
      for (int d = 0; d < kDirections; ++d) {
        if (!grid.canMove(here, d)) continue;
        const Cell next = step(here, d);
        if (!window.contains(next)) continue;
        const auto j = static_cast<std::uint32_t>(window.slot(next));
        if (result.distance[j] == 0.0) continue;
        result.distance[j] = 0.0;
        frontier.push_back(j);
      }
    }
    return result;
  }

  std::priority_queue<detail::SearchEntry, std::vector<detail::SearchEntry>, std::greater<detail::SearchEntry>> open;
  open.push({estimate(request.source), 0.0, source});
  while (!open.empty()) {
    const detail::SearchEntry top = open.top();
    open.pop();
    if (top.cost > result.distance[top.slot]) continue;  // settled before, by a shorter way
    result.largest_distance = std::max(result.largest_distance, top.cost);
    if (top.slot == target_slot) break;
    const Cell here = window.cellAt(top.slot);
    for (int d = 0; d < kDirections; ++d) {
      if (!grid.canMove(here, d)) continue;
      const Cell next = step(here, d);
      if (!window.contains(next)) continue;
      const auto j = static_cast<std::uint32_t>(window.slot(next));
      const double g = top.cost + (request.reverse_costs ? grid.moveCostInto(grid.index(here), d)
                                                         : grid.moveCost(here, d));
      if (g >= result.distance[j]) continue;
      result.distance[j] = g;
      if (request.keep_moves) result.came_dir[j] = static_cast<std::uint8_t>(d);
      open.push({g + estimate(next), g, j});
    }
  }
  return result;
}

}  // namespace eaci
