// The nearest free cell to a cell (a goal in an obstacle moves there, within a tolerance).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"

namespace eaci {

// The free cell of `view` nearest to `cell` (Euclidean distance between centres, in cells) within
// `radius_cells`: `cell` itself if free; of equally near cells the first in row-major order;
// none if no free cell lies within the radius. `cell` may lie off the map.
inline std::optional<Cell> nearestFreeCell(const GridView& view, Cell cell, double radius_cells) {
  if (view.isFree(cell)) return cell;
  if (!(radius_cells >= 0)) return std::nullopt;  // also NaN
  const double reach_real = std::floor(std::min(radius_cells, double(view.width() + view.height())));
  const int reach = static_cast<int>(reach_real);
  std::optional<Cell> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int dr = -reach; dr <= reach; ++dr) {
    for (int dc = -reach; dc <= reach; ++dc) {
      const long long row = static_cast<long long>(cell.row) + dr, col = static_cast<long long>(cell.col) + dc;
      if (row < 0 || col < 0 || row >= view.height() || col >= view.width()) continue;
      const double distance = std::hypot(dr, dc);
      const Cell candidate{static_cast<int>(row), static_cast<int>(col)};
      if (distance > radius_cells || distance >= best_distance || !view.isFree(candidate)) continue;
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace eaci
