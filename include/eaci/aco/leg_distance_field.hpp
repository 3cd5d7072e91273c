// Exact grid distance to the island an ant is heading for, the leg heuristic of the
// geodesic island strategy (beyond the paper; the paper uses the straight-line distance).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "eaci/aco/islands.hpp"
#include "eaci/grid/binary_grid.hpp"

namespace eaci {

// Grid distance to one island, computed in a window around its leg (the leg's cells plus a
// margin). Cells the window does not reach read as the Euclidean distance, raised to at least
// one more than the largest distance inside the window, so they never look better.
class LegDistanceField {
 public:
  LegDistanceField() = default;

  // `leg` is the part of the shortest route from the previous island to `target`.
  LegDistanceField(const BinaryGrid& grid, const CellPath& leg, Cell target) : target_(target) {
    int r0 = target.row, r1 = target.row, c0 = target.col, c1 = target.col;
    for (const Cell& c : leg) {
      r0 = std::min(r0, c.row);
      r1 = std::max(r1, c.row);
      c0 = std::min(c0, c.col);
      c1 = std::max(c1, c.col);
    }
    const int margin = std::max(4, static_cast<int>(leg.size()) / 2);
    row0_ = std::max(0, r0 - margin);
    col0_ = std::max(0, c0 - margin);
    rows_ = std::min(grid.height() - 1, r1 + margin) - row0_ + 1;
    cols_ = std::min(grid.width() - 1, c1 + margin) - col0_ + 1;
    distance_.assign(static_cast<std::size_t>(rows_) * static_cast<std::size_t>(cols_),
                     std::numeric_limits<double>::infinity());
    fillByDijkstra(grid);
  }

  // Grid distance (cells) from `c` to the island.
  double at(Cell c) const {
    const int r = c.row - row0_, k = c.col - col0_;
    if (r >= 0 && k >= 0 && r < rows_ && k < cols_) {
      const double d = distance_[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_) + static_cast<std::size_t>(k)];
      if (std::isfinite(d)) return d;
    }
    return std::max(euclidean(c, target_), outside_);
  }

 private:
  bool inWindow(Cell c) const {
    return c.row >= row0_ && c.col >= col0_ && c.row < row0_ + rows_ && c.col < col0_ + cols_;
  }
  std::size_t slot(Cell c) const {
    return static_cast<std::size_t>(c.row - row0_) * static_cast<std::size_t>(cols_) +
           static_cast<std::size_t>(c.col - col0_);
  }

  void fillByDijkstra(const BinaryGrid& grid) {
    using Entry = std::pair<double, std::uint32_t>;  // distance, window slot
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    distance_[slot(target_)] = 0.0;
    open.push({0.0, static_cast<std::uint32_t>(slot(target_))});
    double largest = 0.0;
    while (!open.empty()) {
      const auto [d, s] = open.top();
      open.pop();
      if (d > distance_[s]) continue;
      largest = std::max(largest, d);
      const Cell here{row0_ + static_cast<int>(s / static_cast<std::uint32_t>(cols_)),
                      col0_ + static_cast<int>(s % static_cast<std::uint32_t>(cols_))};
      for (int dir = 0; dir < kDirections; ++dir) {
        // The move rule is symmetric, so distances *from* the island are distances *to* it.
        if (!grid.canMove(here, dir)) continue;
        const Cell next = step(here, dir);
        if (!inWindow(next)) continue;
        const double nd = d + stepLength(dir);
        if (nd < distance_[slot(next)]) {
          distance_[slot(next)] = nd;
          open.push({nd, static_cast<std::uint32_t>(slot(next))});
        }
      }
    }
    outside_ = largest + 1.0;
  }

  Cell target_{};
  int row0_ = 0, col0_ = 0, rows_ = 0, cols_ = 0;
  std::vector<double> distance_;
  double outside_ = 0.0;
};

// One field per island after S (index = the island's index), read by the ant walk.
inline std::vector<LegDistanceField> legDistanceFields(const BinaryGrid& grid, const CellPath& shortest_route,
                                                       const std::vector<Cell>& islands) {
  std::vector<LegDistanceField> fields(islands.size());
  std::size_t from = 0;
  for (std::size_t z = 1; z < islands.size(); ++z) {
    std::size_t to = from;
    while (to < shortest_route.size() && !(shortest_route[to] == islands[z])) ++to;
    const CellPath leg(shortest_route.begin() + static_cast<std::ptrdiff_t>(from),
                       shortest_route.begin() + static_cast<std::ptrdiff_t>(std::min(to + 1, shortest_route.size())));
    fields[z] = LegDistanceField(grid, leg, islands[z]);
    from = to;
  }
  return fields;
}

}  // namespace eaci
