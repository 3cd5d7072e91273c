// A rectangle of cells, numbered row-major ("slots"): the part of a grid a search stays in, or
// the box a colony's region is numbered in.
#pragma once

#include <algorithm>
#include <cstddef>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cost_grid.hpp"

namespace eaci {

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

}  // namespace eaci
