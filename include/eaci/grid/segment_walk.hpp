// The one walk of a straight segment over the grid: the smoother prices its shortcuts with it,
// the planning service checks every route and every pose-to-pose segment it sends with it.
//
// Cell (row r, column c) spans x in [c - 1/2, c + 1/2] and y in [r - 1/2, r + 1/2] in cell
// coordinates (CellPoint: x = column, y = row, centres at whole numbers). The walk visits every
// cell whose inside the segment crosses, in order, each with the segment's length inside it.
// Where the segment passes exactly through a cell corner it moves diagonally, and the two cells
// beside that corner are visited too, with length 0 (a robot on that line touches them); so
// are the cells beyond `to` when it lies on a border or a corner.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_point.hpp"

namespace eaci {

namespace detail {

// The index of the cell a walk starting at coordinate `v` and moving by `d` along that axis
// begins in: the cell containing v, or, for a v on a border, the cell ahead of it.
inline int firstCellIndex(double v, double d) {
  return static_cast<int>(d < 0 ? std::ceil(v - 0.5) : std::floor(v + 0.5));
}

}  // namespace detail

// Visits the cells the segment from `from` to `to` passes, as above; `visit(cell, length)`
// returns false to stop the walk. Crossing times are computed from the endpoints for each
// border (never accumulated), and two within 1e-10 of the segment are one corner: for segments
// between cell centres on grids below 70 000 cells a side, distinct crossings lie further apart.
template <class Visit>
void walkSegment(const CellPoint& from, const CellPoint& to, Visit&& visit) {
  constexpr double kSame = 1e-10;
  const double dx = to.x() - from.x(), dy = to.y() - from.y();
  const double total = std::hypot(dx, dy);
  const int step_col = dx > 0 ? 1 : -1, step_row = dy > 0 ? 1 : -1;
  Cell cell{detail::firstCellIndex(from.y(), dy), detail::firstCellIndex(from.x(), dx)};
  constexpr double kNever = std::numeric_limits<double>::infinity();
  // When the segment leaves `cell` across its column border, and across its row border.
  const auto col_exit = [&](const Cell& c) { return dx != 0 ? (c.col + 0.5 * step_col - from.x()) / dx : kNever; };
  const auto row_exit = [&](const Cell& c) { return dy != 0 ? (c.row + 0.5 * step_row - from.y()) / dy : kNever; };
  double t = 0.0;
  for (;;) {
    const double col_t = col_exit(cell), row_t = row_exit(cell);
    const double exit_t = std::min(col_t, row_t);
    if (exit_t >= 1.0 - kSame) {  // `to` lies in this cell, or on its far border or corner
      if (!visit(cell, (1.0 - t) * total)) return;
      const bool on_col = col_t <= 1.0 + kSame, on_row = row_t <= 1.0 + kSame;  // the cells `to` touches beyond
      if (on_col && !visit(Cell{cell.row, cell.col + step_col}, 0.0)) return;
      if (on_row && !visit(Cell{cell.row + step_row, cell.col}, 0.0)) return;
      if (on_col && on_row) visit(Cell{cell.row + step_row, cell.col + step_col}, 0.0);
      return;
    }
    if (!visit(cell, (exit_t - t) * total)) return;
    t = exit_t;
    if (std::abs(col_t - row_t) <= kSame) {  // through a corner: both cells beside it are touched
      if (!visit(Cell{cell.row, cell.col + step_col}, 0.0) || !visit(Cell{cell.row + step_row, cell.col}, 0.0)) return;
      cell = Cell{cell.row + step_row, cell.col + step_col};
    } else if (col_t < row_t) {
      cell.col += step_col;
    } else {
      cell.row += step_row;
    }
  }
}

// The walk between two cell centres.
template <class Visit>
void traverseSegment(Cell from, Cell to, Visit&& visit) {
  walkSegment(cellPoint(from), cellPoint(to), visit);
}

}  // namespace eaci
