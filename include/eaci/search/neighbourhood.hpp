// One step of every search: the neighbours of a cell in the search's window, and the labelling
// of those a move reaches more cheaply.
#pragma once

#include <cstddef>
#include <cstdint>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_window.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/moves.hpp"
#include "eaci/grid/window_moves.hpp"

namespace eaci {
namespace detail {

// The neighbours of a cell by direction, as window slot and grid index offsets, and the
// allowed moves from a cell that stay in the window (WindowMoves).
class SearchNeighbourhood {
 public:
  SearchNeighbourhood(const CostGrid& grid, const CellWindow& window) : moves_(grid, window) {
    for (int d = 0; d < kDirections; ++d) {
      slot_step_[d] = static_cast<std::ptrdiff_t>(kDirRow[d]) * window.cols + kDirCol[d];
      index_step_[d] = static_cast<std::ptrdiff_t>(kDirRow[d]) * grid.width() + kDirCol[d];
    }
  }

  std::uint32_t slotTowards(std::uint32_t slot, int dir) const {
    return static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(slot) + slot_step_[dir]);
  }
  std::size_t indexTowards(std::size_t index, int dir) const {
    return static_cast<std::size_t>(static_cast<std::ptrdiff_t>(index) + index_step_[dir]);
  }
  // Bit d: the move in direction d from `here` is allowed and ends in the window.
  unsigned movesFrom(Cell here) const { return moves_.from(here); }

 private:
  WindowMoves moves_;
  std::ptrdiff_t slot_step_[kDirections];
  std::ptrdiff_t index_step_[kDirections];
};

inline int lowestBit(unsigned bits) { return __builtin_ctz(bits); }

// Labels each cell one allowed move from the settled cell `here` (window slot `slot`, route
// cost `cost`) that the move reaches more cheaply than its label says, and hands it to
// on_label(slot, cell, cost). A move costs by the cell it enters; with `reverse_costs` by the
// cell it leaves (the real move goes the other way: costs of routes *to* the source).
// `Labels`: cost(slot) (+infinity when not reached), label(slot, cost, move) and kept(cost),
// the cost as the labels keep it (rounded to float by the meeting search's).
template <class Labels, class OnLabel>
void relaxMoves(const CostGrid& grid, const SearchNeighbourhood& around, std::uint32_t slot, Cell here, double cost,
                bool reverse_costs, Labels& labels, const OnLabel& on_label) {
  const std::size_t index = grid.index(here);
  for (unsigned moves = around.movesFrom(here); moves != 0; moves &= moves - 1) {
    const int d = lowestBit(moves);
    const std::uint32_t j = around.slotTowards(slot, d);
    const double g = labels.kept(cost + grid.moveCostInto(reverse_costs ? index : around.indexTowards(index, d), d));
    if (g >= labels.cost(j)) continue;
    labels.label(j, g, static_cast<std::uint8_t>(d));
    on_label(j, step(here, d), g);
  }
}

}  // namespace detail
}  // namespace eaci
