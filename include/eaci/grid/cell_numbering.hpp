// The paper's serial numbering and cell-centre coordinates (Eq. 1-4).
#pragma once

#include <Eigen/Core>

#include <cstdint>

#include "eaci/grid/cell.hpp"

namespace eaci {

// Eq. 1-2 read backwards: the cell of serial number g in 1..W*H (numbered left to right, top to
// bottom): row = ceil(g / W) - 1, column = g - (row)*W - 1 (both 0-based).
inline Cell cellFromSerial(std::int64_t g, int width) {
  const std::int64_t row = (g - 1) / width;
  return Cell{static_cast<int>(row), static_cast<int>(g - 1 - row * width)};
}

// Eq. 3-4: centre of the cell, origin at the bottom-left corner of the map, y up,
// cell size a. With 1-based r, c: x = (c - 0.5) a, y = (H - r + 0.5) a.
inline Eigen::Vector2d cellCentre(Cell c, int height, double cell_size = 1.0) {
  return {(c.col + 0.5) * cell_size, (height - c.row - 0.5) * cell_size};
}

}  // namespace eaci
