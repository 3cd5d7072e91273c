// MAACO's elliptical initial pheromone (re-implemented from public descriptions, not the
// authors' code): tau(i) = C d_ST / (d_Si + d_iT), largest (C) on the segment S-E and falling
// off across the ellipses with foci S and E. Kept on edges: the move i -> j takes the value of
// the cell it enters, j (docs/algorithm.md, MAACO, choice 9).
#pragma once

#include <cstdint>
#include <utility>

#include "eaci/aco/colony_region.hpp"
#include "eaci/aco/maaco_heuristic.hpp"
#include "eaci/aco/pheromone_field.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci {

// C d_ST / (d_Sj + d_jT) for cell j; C when j is on the segment (S != E).
inline double ellipticalPheromone(Cell j, Cell start, Cell goal, double c) {
  return c * straightDistance(start, goal) / (straightDistance(start, j) + straightDistance(j, goal));
}

// Every allowed move of the region's cells at ellipticalPheromone of the cell it enters.
// `reuse`: a field whose memory the new one takes over. `stop`: ticked once per cell; stopped,
// the field is unfinished (the caller reads stop->stopped()).
inline PheromoneField ellipticalInitialPheromone(const CostGrid& grid, const ColonyRegion& region, Cell start, Cell goal,
                                                 double c, double alpha, PheromoneField reuse = {},
                                                 StopPoll* stop = nullptr) {
  PheromoneField field = std::move(reuse);
  field.reset(region.size(), c, alpha);
  for (std::uint32_t r = 0; r < region.size(); ++r) {
    if (stop != nullptr && stop->tick()) return field;
    const Cell from = grid.cellAt(region.gridIndex(r));
    for (unsigned moves = region.moves(r); moves != 0; moves &= moves - 1) {
      const int d = __builtin_ctz(moves);
      field.set(r, d, ellipticalPheromone(step(from, d), start, goal, c));
    }
  }
  field.refreshChanged();
  return field;
}

}  // namespace eaci
