// The clearance of straight lines over the grid, looked for near the lines only: the smallest
// distance, in cells, from a segment or polyline to the centre of an obstacle cell
// (CostGrid::kObstacle). The one clearance measure: the metrics (minPolylineClearance,
// metrics/path_metrics.hpp) bound the reach by a distance transform of the whole map, corner
// rounding (path/smoothing.hpp) by the clearance it has to keep.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_point.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/nearest_free.hpp"

namespace eaci {

// The distance from the segment p -> q to the nearest obstacle cell's centre if it is below
// `reach`, else `reach`: only the cells within reach of the segment are looked at, about
// (|pq| + 2 reach) x 2 reach of them (the segment is cut into pieces of at most 4 cells, each
// with its own window). Cells off the grid are not obstacles.
inline double segmentClearanceWithin(const CostGrid& grid, const CellPoint& p, const CellPoint& q, double reach) {
  double best = reach;
  if (!(reach > 0)) return best;
  const std::uint8_t* cells = grid.cellBytes();
  const int pieces = std::max(1, static_cast<int>(std::ceil((q - p).norm() / 4.0)));
  for (int i = 0; i < pieces; ++i) {
    const CellPoint a = p + (q - p) * (static_cast<double>(i) / pieces);
    const CellPoint b = p + (q - p) * (static_cast<double>(i + 1) / pieces);
    const CellPoint d = b - a;
    const double length2 = d.squaredNorm();
    const int r0 = std::max(0, static_cast<int>(std::floor(std::min(a.y(), b.y()) - best)));
    const int r1 = std::min(grid.height() - 1, static_cast<int>(std::ceil(std::max(a.y(), b.y()) + best)));
    const int c0 = std::max(0, static_cast<int>(std::floor(std::min(a.x(), b.x()) - best)));
    const int c1 = std::min(grid.width() - 1, static_cast<int>(std::ceil(std::max(a.x(), b.x()) + best)));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) {
        if (cells[grid.index(Cell{r, c})] != CostGrid::kObstacle) continue;
        const CellPoint o(c, r);
        const double t = length2 > 0 ? std::clamp((o - a).dot(d) / length2, 0.0, 1.0) : 0.0;
        best = std::min(best, (a + t * d - o).norm());
      }
  }
  return best;
}

// The distance from the polyline through the cell centres `corners` to the nearest obstacle
// cell's centre if it is below `reach`, else `reach` (segmentClearanceWithin, each segment
// looking no farther than the best so far; the corners' own clearance, from a ring search
// around each, bounds it first).
inline double polylineClearanceWithin(const CostGrid& grid, const CellPath& corners, double reach) {
  double best = reach;
  const auto obstacle = [&](Cell c) { return grid.isBlocked(c); };
  for (const Cell& corner : corners) {
    const std::optional<Cell> nearest = nearestCellWhere(grid.width(), grid.height(), corner, best, obstacle);
    if (nearest) best = std::min(best, std::hypot(nearest->row - corner.row, nearest->col - corner.col));
  }
  for (std::size_t k = 1; k < corners.size(); ++k)
    best = segmentClearanceWithin(grid, cellPoint(corners[k - 1]), cellPoint(corners[k]), best);
  return best;
}

}  // namespace eaci
