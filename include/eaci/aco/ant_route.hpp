// The route one ant walked in one iteration.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace eaci {

struct AntRoute {
  bool complete = false;              // reached E; a lost ant's route is incomplete
  double length = 0.0;                // cells: straight step 1, diagonal sqrt 2
  // L_k: the sum of its move costs (= length on a binary map), plus turn_cost x its heading
  // change in radians when turns are priced (WalkSetup::priceTurns)
  double cost = 0.0;
  std::vector<std::uint32_t> cells;   // cells of the colony's region (ColonyRegion numbers), start first
  std::vector<std::uint8_t> dirs;     // dirs[k]: direction of the move cells[k] -> cells[k+1]

  void reset(std::uint32_t start) {
    complete = false;
    length = 0.0;
    cost = 0.0;
    cells.clear();
    dirs.clear();
    cells.push_back(start);
  }
};

// The route's turns: the moves whose direction differs from the one before.
inline int turnCount(const AntRoute& route) {
  int turns = 0;
  for (std::size_t k = 1; k < route.dirs.size(); ++k) turns += route.dirs[k] != route.dirs[k - 1] ? 1 : 0;
  return turns;
}

}  // namespace eaci
