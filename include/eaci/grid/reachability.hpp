// Which cells can be reached from a cell under the grid's move rule.
#pragma once

#include <cstdint>
#include <vector>

#include "eaci/grid/binary_grid.hpp"

namespace eaci {

// Flag per cell (index order of the grid): 1 if reachable from `from`.
inline std::vector<std::uint8_t> reachableFrom(const BinaryGrid& grid, Cell from) {
  std::vector<std::uint8_t> reached(grid.cellCount(), 0);
  if (!grid.isFree(from)) return reached;
  std::vector<std::size_t> frontier{grid.index(from)};
  reached[grid.index(from)] = 1;
  while (!frontier.empty()) {
    const Cell cell = grid.cellAt(frontier.back());
    frontier.pop_back();
    for (int d = 0; d < kDirections; ++d) {
      if (!grid.canMove(cell, d)) continue;
      const std::size_t next = grid.index(step(cell, d));
      if (reached[next]) continue;
      reached[next] = 1;
      frontier.push_back(next);
    }
  }
  return reached;
}

}  // namespace eaci
