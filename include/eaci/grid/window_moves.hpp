// The per-cell move mask of every search and region over a grid: the allowed moves from a cell
// (CostGrid::movesFrom) that end inside a window (CellWindow). On the whole grid it is
// CostGrid::movesFrom itself.
#pragma once

#include <algorithm>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_window.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

class WindowMoves {
 public:
  // `grid` and `window` must outlive it.
  WindowMoves(const CostGrid& grid, const CellWindow& window)
      : grid_(grid), window_(window),
        row_lo_(std::max(0, window.row0)), row_hi_(std::min(grid.height(), window.row0 + window.rows)),
        col_lo_(std::max(0, window.col0)), col_hi_(std::min(grid.width(), window.col0 + window.cols)) {}

  // Bit d: the move in direction d from `here` is allowed and ends in the window. Cells off the
  // window's border (all eight neighbours inside it) skip the window checks.
  unsigned from(Cell here) const {
    const unsigned moves = grid_.movesFrom(here);
    if (here.row > row_lo_ && here.row + 1 < row_hi_ && here.col > col_lo_ && here.col + 1 < col_hi_) return moves;
    unsigned in_window = 0;
    for (int d = 0; d < kDirections; ++d) in_window |= static_cast<unsigned>(window_.contains(step(here, d))) << d;
    return moves & in_window;
  }

 private:
  const CostGrid& grid_;
  const CellWindow& window_;
  int row_lo_, row_hi_, col_lo_, col_hi_;  // window and grid overlap: rows [row_lo_, row_hi_), columns likewise
};

}  // namespace eaci
