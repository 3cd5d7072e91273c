// The auxiliary map (Eq. 12): free cells that could trap an ant become obstacles.
#pragma once

#include <cstdint>
#include <vector>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci {

// How cells outside the map count in Eq. 12. The paper does not say.
// kFree is the default: with kObstacle every free cell of the map border that
// touches an obstacle (and every corner cell) would be blocked.
enum class AuxiliaryBorder { kFree, kObstacle };

// Eq. 12 for one free cell of the map: true when it becomes an obstacle, because two
// perpendicular 4-neighbours are obstacles: (left & up), (up & right), (right & down) or
// (down & left). `start` and `goal` are never converted.
inline bool auxiliaryConverts(const CostGrid& original, Cell cell, Cell start, Cell goal,
                              AuxiliaryBorder border = AuxiliaryBorder::kFree) {
  if (cell == start || cell == goal) return false;
  auto blocked = [&](int r, int c) {
    const Cell n{r, c};
    if (!original.contains(n)) return border == AuxiliaryBorder::kObstacle;
    return original.isBlocked(n);
  };
  const int r = cell.row, c = cell.col;
  const bool left = blocked(r, c - 1), up = blocked(r - 1, c);
  const bool right = blocked(r, c + 1), down = blocked(r + 1, c);
  return (left && up) || (up && right) || (right && down) || (down && left);
}

// Is `cell` free on the auxiliary map? Eq. 12 evaluated at that one cell, without the map.
inline bool freeOnAuxiliaryMap(const CostGrid& original, Cell cell, Cell start, Cell goal,
                               AuxiliaryBorder border = AuxiliaryBorder::kFree) {
  return original.isFree(cell) && !auxiliaryConverts(original, cell, start, goal, border);
}

// The auxiliary map of Eq. 12: one pass reading the original map only.
// `stop`: ticked once per row; stopped, the map is unfinished (the caller reads stop->stopped()).
inline CostGrid auxiliaryMap(const CostGrid& original, Cell start, Cell goal,
                               AuxiliaryBorder border = AuxiliaryBorder::kFree, StopPoll* stop = nullptr) {
  CostGrid aux = original;
  for (int r = 0; r < original.height(); ++r) {
    if (stop != nullptr && stop->tick(static_cast<std::size_t>(original.width()))) return aux;
    for (int c = 0; c < original.width(); ++c) {
      const Cell cell{r, c};
      if (original.isBlocked(cell)) continue;
      if (auxiliaryConverts(original, cell, start, goal, border)) aux.setBlocked(cell, true);
    }
  }
  return aux;
}

}  // namespace eaci
