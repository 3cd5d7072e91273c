#include "route_defect.hpp"

#include <cstdlib>

namespace eaci_service {
namespace {

std::string describe(eaci::Cell c) { return "(row " + std::to_string(c.row) + ", col " + std::to_string(c.col) + ")"; }

// "" when the straight segment between the centres of `a` and `b` passes only passable cells.
// Cell (r, c) spans columns c - 1/2 .. c + 1/2 and rows r - 1/2 .. r + 1/2. Going from a to b
// (dc = |b.col - a.col| columns, dr = |b.row - a.row| rows), the line crosses its k-th column
// border at the fraction (2k - 1) / (2 dc) of the way and its j-th row border at
// (2j - 1) / (2 dr): comparing (2k - 1) dr with (2j - 1) dc says which comes first, or that
// both come at once (a corner).
std::string segmentDefect(const eaci::GridView& view, eaci::Cell a, eaci::Cell b, bool allow_corner_cutting) {
  const long long dc = std::llabs(static_cast<long long>(b.col) - a.col);
  const long long dr = std::llabs(static_cast<long long>(b.row) - a.row);
  const int step_col = b.col > a.col ? 1 : -1, step_row = b.row > a.row ? 1 : -1;
  eaci::Cell cell = a;
  if (!view.isFree(cell)) return "it starts in a blocked cell " + describe(cell);
  long long k = 1, j = 1;  // the next column border and the next row border to cross
  while (k <= dc || j <= dr) {
    const long long col_at = k <= dc ? (2 * k - 1) * dr : -1;  // -1: no column border left
    const long long row_at = j <= dr ? (2 * j - 1) * dc : -1;
    if (row_at < 0 || (col_at >= 0 && col_at < row_at)) {
      cell.col += step_col;
      ++k;
    } else if (col_at < 0 || row_at < col_at) {
      cell.row += step_row;
      ++j;
    } else {  // through the corner: diagonally
      const eaci::Cell beside_col{cell.row, cell.col + step_col}, beside_row{cell.row + step_row, cell.col};
      if (!allow_corner_cutting && (!view.isFree(beside_col) || !view.isFree(beside_row)))
        return "it passes a blocked cell's corner between " + describe(beside_col) + " and " + describe(beside_row);
      cell.col += step_col;
      cell.row += step_row;
      ++k;
      ++j;
    }
    if (!view.isFree(cell)) return "it crosses the blocked cell " + describe(cell);
  }
  return "";
}

}  // namespace

std::string routeDefect(const eaci::GridView& view, const eaci::CellPath& route, eaci::Cell from, eaci::Cell to,
                        bool allow_corner_cutting) {
  for (std::size_t i = 1; i < route.size(); ++i) {
    const int dr = route[i].row - route[i - 1].row, dc = route[i].col - route[i - 1].col;
    if (std::abs(dr) > 1 || std::abs(dc) > 1 || (dr == 0 && dc == 0)) return "it jumps at cell " + std::to_string(i);
  }
  // Each move is a segment of one cell: the segment walk checks its cells and the corner rule.
  return drivableRouteDefect(view, route, from, to, allow_corner_cutting);
}

std::string drivableRouteDefect(const eaci::GridView& view, const eaci::CellPath& corners, eaci::Cell from,
                                eaci::Cell to, bool allow_corner_cutting) {
  if (corners.empty() || !(corners.front() == from) || !(corners.back() == to)) return "it does not join start and goal";
  if (corners.size() == 1 && !view.isFree(corners.front())) return "its only cell is blocked";
  for (std::size_t i = 1; i < corners.size(); ++i) {
    const std::string defect = segmentDefect(view, corners[i - 1], corners[i], allow_corner_cutting);
    if (!defect.empty())
      return "segment " + std::to_string(i) + " of " + std::to_string(corners.size() - 1) + ", " +
             describe(corners[i - 1]) + " to " + describe(corners[i]) + ": " + defect;
  }
  return "";
}

}  // namespace eaci_service
