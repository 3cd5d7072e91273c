// Islands that cost nothing (beyond the paper): the paper's idea of short legs between
// waypoints and favourable regions between them, with the waypoints placed on a cheapest
// route (a shortest one on a binary map) instead of near the straight line S-E, and each leg
// guided by its exact cost.
#pragma once

#include <algorithm>
#include <vector>

#include "eaci/aco/islands.hpp"
#include "eaci/grid/cell.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// Islands on the cheapest route (`shortest_route`, e.g. A*'s): after S, the first cell of the route at least r_s
// (Eq. 13) further along it that the auxiliary map leaves free, and so on; E is the last
// island once it is within r_s along the route. The route through the islands is the
// cheapest route, and consecutive legs never overlap. With `max_spacing` > 0, r_s is capped
// at that many cells: on large maps long legs would leave the ants' heuristic too flat to
// guide them (1/d^beta barely differs between neighbours when d is large).
// `free_on_auxiliary(cell)` says whether the auxiliary map leaves a route cell free.
template <class FreeOnAuxiliary>
std::vector<Cell> geodesicIslands(const FreeOnAuxiliary& free_on_auxiliary, const CellPath& shortest_route,
                                  Cell start, Cell goal, int island_count, double max_spacing = 0.0) {
  std::vector<Cell> islands{start};
  if (start == goal || shortest_route.size() < 2) {
    if (!(start == goal)) islands.push_back(goal);
    return islands;
  }
  double spacing = searchRadius(start, goal, island_count);
  if (max_spacing > 0) spacing = std::min(spacing, max_spacing);
  std::vector<double> along(shortest_route.size(), 0.0);  // route length from S to each cell
  for (std::size_t k = 1; k < shortest_route.size(); ++k)
    along[k] = along[k - 1] + stepLengthBetween(shortest_route[k - 1], shortest_route[k]);
  const double total = along.back();
  double last = 0.0;
  for (std::size_t k = 1; k + 1 < shortest_route.size(); ++k) {
    if (total - last <= spacing + 1e-9) break;  // E is within r_s of the last island
    if (along[k] - last < spacing - 1e-9 || !free_on_auxiliary(shortest_route[k])) continue;
    islands.push_back(shortest_route[k]);
    last = along[k];
  }
  islands.push_back(goal);
  return islands;
}

}  // namespace eaci
