// The length of a route of cells: the polyline through the cells' centres, in cells.
#pragma once

#include <cmath>
#include <cstddef>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// Straight step 1, diagonal sqrt 2 (a jump between cells that are not neighbours, such as a
// smoothed route's, counts its straight-line length).
inline double pathLength(const CellPath& path) {
  double length = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const int dir = directionBetween(path[k - 1], path[k]);
    if (dir >= 0) {
      length += stepLength(dir);
    } else {
      length += std::hypot(static_cast<double>(path[k].col - path[k - 1].col),
                           static_cast<double>(path[k].row - path[k - 1].row));
    }
  }
  return length;
}

}  // namespace eaci
