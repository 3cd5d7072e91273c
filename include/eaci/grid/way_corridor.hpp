// The corridor of a way: the grid with every cell farther than `radius` cells (centre to
// centre, Euclidean) from each cell of a route made an obstacle. A plan inside it takes the
// same gaps and doors as the route (the way), and is free to shape itself within them: the
// planner chooses the way by one weighting of the costs and the route within it by another
// (Parameters::way_cost_factor, planner.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci {

// The cell offsets (row, col) within `radius` cells of a cell: dr^2 + dc^2 <= radius^2.
inline std::vector<Cell> discOffsets(int radius) {
  std::vector<Cell> offsets;
  for (int dr = -radius; dr <= radius; ++dr)
    for (int dc = -radius; dc <= radius; ++dc)
      if (dr * dr + dc * dc <= radius * radius) offsets.push_back(Cell{dr, dc});
  return offsets;
}

// `grid` with every cell farther than `radius` cells from every cell of `way` blocked (the
// way's own cells and those near them keep their costs). `stop` is ticked per way cell and per
// row; once it says stop the returned grid is unfinished (the caller reads stop->stopped()).
inline CostGrid wayCorridor(const CostGrid& grid, const CellPath& way, int radius, StopPoll* stop = nullptr) {
  std::vector<std::uint8_t> inside(grid.cellCount(), 0);
  const std::vector<Cell> disc = discOffsets(radius);
  for (const Cell& c : way) {
    for (const Cell& d : disc) {
      const Cell cell{c.row + d.row, c.col + d.col};
      if (grid.contains(cell)) inside[grid.index(cell)] = 1;
    }
    if (stop != nullptr && stop->tick(disc.size())) return grid;
  }
  CostGrid corridor = grid;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const Cell cell{row, col};
      if (!inside[grid.index(cell)] && !grid.isBlocked(cell)) corridor.setBlocked(cell, true);
    }
    if (stop != nullptr && stop->tick(static_cast<std::size_t>(grid.width()))) return corridor;
  }
  return corridor;
}

}  // namespace eaci
