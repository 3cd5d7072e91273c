// Path metrics of the paper's tables: route length and total corner angle.
#pragma once

#include <cmath>
#include <cstddef>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// Length in cells: straight step 1, diagonal sqrt 2 (a jump between cells that are not
// neighbours, which no planner returns, counts its straight-line length).
inline double pathLength(const CellPath& path) {
  double length = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const int dir = directionBetween(path[k - 1], path[k]);
    length += dir >= 0 ? stepLength(dir)
                       : std::hypot(path[k].row - path[k - 1].row, path[k].col - path[k - 1].col);
  }
  return length;
}

// Sum of the turning angles at the path's inner cells, degrees (multiples of 45 on an
// 8-connected path; other steps count the angle between their straight lines).
inline double totalTurnDegrees(const CellPath& path) {
  constexpr double kDegreesPerRadian = 57.295779513082320876798;
  double total = 0.0;
  for (std::size_t k = 2; k < path.size(); ++k) {
    const double a = std::atan2(path[k - 1].row - path[k - 2].row, path[k - 1].col - path[k - 2].col);
    const double b = std::atan2(path[k].row - path[k - 1].row, path[k].col - path[k - 1].col);
    double turn = std::abs(b - a) * kDegreesPerRadian;
    if (turn > 180.0) turn = 360.0 - turn;
    total += turn;
  }
  return std::round(total * 1e9) / 1e9;
}

}  // namespace eaci
