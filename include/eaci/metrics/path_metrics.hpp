// Path metrics of the paper's tables: route length and total corner angle.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstddef>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// The move from cell a to cell b as a vector in cell units: x columns right, y rows down.
inline Eigen::Vector2d moveVector(Cell a, Cell b) {
  return {static_cast<double>(b.col - a.col), static_cast<double>(b.row - a.row)};
}

// Length in cells: straight step 1, diagonal sqrt 2 (a jump between cells that are not
// neighbours, which no planner returns, counts its straight-line length).
inline double pathLength(const CellPath& path) {
  double length = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const int dir = directionBetween(path[k - 1], path[k]);
    if (dir >= 0) {
      length += stepLength(dir);
    } else {
      const Eigen::Vector2d move = moveVector(path[k - 1], path[k]);
      length += std::hypot(move.x(), move.y());
    }
  }
  return length;
}

// Sum of the turning angles at the path's inner cells, degrees (multiples of 45 on an
// 8-connected path; other steps count the angle between their straight lines).
inline double totalTurnDegrees(const CellPath& path) {
  constexpr double kDegreesPerRadian = 57.295779513082320876798;
  double total = 0.0;
  for (std::size_t k = 2; k < path.size(); ++k) {
    const Eigen::Vector2d in = moveVector(path[k - 2], path[k - 1]);
    const Eigen::Vector2d out = moveVector(path[k - 1], path[k]);
    const double a = std::atan2(in.y(), in.x());
    const double b = std::atan2(out.y(), out.x());
    double turn = std::abs(b - a) * kDegreesPerRadian;
    if (turn > 180.0) turn = 360.0 - turn;
    total += turn;
  }
  return std::round(total * 1e9) / 1e9;
}

}  // namespace eaci
