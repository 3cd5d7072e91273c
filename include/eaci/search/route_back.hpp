// The one way back along a search's labels: from a cell, the move into each cell, to the cell
// the search began at.
#pragma once

#include <cstddef>
#include <cstdint>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_window.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// The label of the cell a search began at: no move leads into it.
constexpr std::uint8_t kNoMove = 0xFF;

// Appends `c` and then each cell the move into the last one came from (`move_into(slot)`, the
// direction of the move into the cell of window slot `slot`; kNoMove at the search's own
// start), ending with that start: the route to `c`, last cell first. `c` must have been reached.
template <class MoveInto>
void appendRouteBack(const CellWindow& window, Cell c, const MoveInto& move_into, CellPath& out) {
  for (;;) {
    out.push_back(c);
    const std::uint8_t d = move_into(window.slot(c));
    if (d == kNoMove) break;
    c = Cell{c.row - kDirRow[d], c.col - kDirCol[d]};
  }
}

}  // namespace eaci
