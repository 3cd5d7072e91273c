// A grid cell addressed by 0-based row (0 = top) and column (0 = left).
#pragma once

#include <cstddef>
#include <vector>

namespace eaci {

struct Cell {
  int row = 0;
  int col = 0;

  friend bool operator==(const Cell& a, const Cell& b) { return a.row == b.row && a.col == b.col; }
  friend bool operator!=(const Cell& a, const Cell& b) { return !(a == b); }
};

using CellPath = std::vector<Cell>;

}  // namespace eaci
