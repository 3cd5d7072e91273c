// The nearest cell to a cell that passes a test, and the nearest free cell (a goal in an
// obstacle moves there, within a tolerance).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci {

// The cell nearest to `cell` that passes a test (Euclidean distance between centres, in cells)
// within `radius_cells`, on a grid of `width` x `height` cells: `cell` itself if it is on the
// grid and passes; of equally near cells the first in row-major order; none if no cell within
// the radius passes. `cell` may lie off the grid; `accept(Cell)` is asked only of cells on it.
//
// The search goes outwards ring by ring (ring k: the cells k rows or columns away, the nearest
// of them exactly k away) and ends once no later ring can hold a cell as near as the best
// found: for an answer d away it visits the rings up to d, about (2 d + 1)^2 cells, whatever
// the radius.
// `should_stop` (a std::function<bool()>, a StopCheck, any callable, or empty) is asked every
// StopPoll::kWorkBetweenChecks cells visited; once it says stop the answer is none (nullopt),
// as if no cell within the radius passed: the caller tells the two apart by its own check.
template <class Accept, class Check = std::function<bool()>>
std::optional<Cell> nearestCellWhere(int width, int height, Cell cell, double radius_cells, const Accept& accept,
                                     const Check& should_stop = Check{}) {
  const auto on_grid = [&](Cell c) { return c.row >= 0 && c.col >= 0 && c.row < height && c.col < width; };
  if (on_grid(cell) && accept(cell)) return cell;
  if (!(radius_cells >= 0)) return std::nullopt;  // also NaN
  const long long row = cell.row, col = cell.col, rows = height, cols = width;
  if (rows <= 0 || cols <= 0) return std::nullopt;
  // The first ring that touches the grid: the Chebyshev distance from `cell` to it.
  const long long first_ring = std::max({0LL, -row, row - (rows - 1), -col, col - (cols - 1)});
  // Every grid cell lies within first_ring + width + height rings (also bounds an infinite radius).
  const long long reach = static_cast<long long>(
      std::floor(std::min(radius_cells, double(first_ring) + double(cols) + double(rows))));
  StopPoll poll(should_stop);
  std::optional<Cell> best;
  long long best_squared = 0;  // dr^2 + dc^2 of `best`: exact, so ties are exact
  // Ranks a candidate: nearer first, then the first in row-major order.
  const auto consider = [&](long long r, long long c) {
    const long long dr = r - row, dc = c - col;
    const long long squared = dr * dr + dc * dc;
    if (best && (squared > best_squared || (squared == best_squared && (r > best->row || (r == best->row && c > best->col)))))
      return;
    if (std::hypot(double(dr), double(dc)) > radius_cells) return;  // the same test as a scan of the square
    const Cell candidate{static_cast<int>(r), static_cast<int>(c)};
    if (!accept(candidate)) return;
    best = candidate;
    best_squared = squared;
  };
  for (long long k = first_ring; k <= reach; ++k) {
    // Ring k's cells are at least k away: none can beat (or tie) a best nearer than that.
    if (best && best_squared < k * k) break;
    const bool top_on_grid = row - k >= 0, bottom_on_grid = row + k < rows;
    const bool left_on_grid = col - k >= 0, right_on_grid = col + k < cols;
    if (!top_on_grid && !bottom_on_grid && !left_on_grid && !right_on_grid) break;  // every grid cell seen
    const long long r0 = std::max(0LL, row - k), r1 = std::min(rows - 1, row + k);
    const long long c0 = std::max(0LL, col - k), c1 = std::min(cols - 1, col + k);
    // Row-major order within the ring: the top row, the two sides row by row, the bottom row.
    if (top_on_grid) {
      if (poll.tick(static_cast<std::size_t>(c1 - c0 + 1))) return std::nullopt;
      for (long long c = c0; c <= c1; ++c) consider(row - k, c);
    }
    if (left_on_grid || right_on_grid) {
      for (long long r = std::max(r0, row - k + 1); r <= std::min(r1, row + k - 1); ++r) {
        if (poll.tick(2)) return std::nullopt;
        if (left_on_grid) consider(r, col - k);
        if (right_on_grid) consider(r, col + k);
      }
    }
    if (bottom_on_grid && k > 0) {
      if (poll.tick(static_cast<std::size_t>(c1 - c0 + 1))) return std::nullopt;
      for (long long c = c0; c <= c1; ++c) consider(row + k, c);
    }
  }
  return best;
}

// The free cell of `view` nearest to `cell` within `radius_cells` (nearestCellWhere: `cell`
// itself if free, ties row-major first, none beyond the radius or once `should_stop` says stop).
template <class Check = std::function<bool()>>
std::optional<Cell> nearestFreeCell(const GridView& view, Cell cell, double radius_cells,
                                    const Check& should_stop = Check{}) {
  return nearestCellWhere(view.width(), view.height(), cell, radius_cells,
                          [&view](Cell c) { return !view.isObstacle(c); }, should_stop);
}

}  // namespace eaci
