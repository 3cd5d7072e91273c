// The octile distance, the heuristic and lower bound of every exact search.
#pragma once

#include <algorithm>
#include <cstdlib>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// The length of the shortest 8-connected path on an empty grid, a consistent A* heuristic
// under both corner rules. No move costs less than its length (the cheapest cell, cost 0,
// weighs a move by exactly 1), so it stays consistent for route costs.
inline double octileDistance(Cell a, Cell b) {
  const int dr = std::abs(a.row - b.row), dc = std::abs(a.col - b.col);
  return (kSqrt2 - 1.0) * std::min(dr, dc) + std::max(dr, dc);
}

}  // namespace eaci
