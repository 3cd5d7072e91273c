// Islands that cost no length (beyond the paper): the paper's idea of short legs between
// waypoints and favourable regions between them, with the waypoints placed on a shortest
// route instead of near the straight line S-E, and each leg guided by its exact grid distance.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "eaci/aco/islands.hpp"
#include "eaci/grid/binary_grid.hpp"

namespace eaci {

// The shortest route from `start` down the grid-distance field of the goal
// (`distance_to_goal`, e.g. distanceField(grid, goal)): each step goes to the neighbour that
// keeps distance + step length equal to the current distance; ties to the lowest direction.
// Empty when the start cannot reach the goal.
inline CellPath descendDistanceField(const BinaryGrid& grid, const std::vector<double>& distance_to_goal, Cell start) {
  CellPath route;
  if (!grid.isFree(start) || !std::isfinite(distance_to_goal[grid.index(start)])) return route;
  route.push_back(start);
  Cell current = start;
  while (distance_to_goal[grid.index(current)] > 0.0) {
    int best_dir = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int d = 0; d < kDirections; ++d) {
      if (!grid.canMove(current, d)) continue;
      const double through = stepLength(d) + distance_to_goal[grid.index(step(current, d))];
      if (through < best - 1e-9) {
        best = through;
        best_dir = d;
      }
    }
    current = step(current, best_dir);  // a finite distance always has a descending neighbour
    route.push_back(current);
  }
  return route;
}

// Islands on the shortest route: after S, the first cell of the route at least r_s
// (Eq. 13) further along it that the auxiliary map leaves free, and so on; E is the last
// island once it is within r_s along the route. The route through the islands is the
// shortest route, and consecutive legs never overlap. With `max_spacing` > 0, r_s is capped
// at that many cells: on large maps long legs would leave the ants' heuristic too flat to
// guide them (1/d^beta barely differs between neighbours when d is large).
inline std::vector<Cell> geodesicIslands(const BinaryGrid& auxiliary, const CellPath& shortest_route, Cell start,
                                         Cell goal, int island_count, double max_spacing = 0.0) {
  std::vector<Cell> islands{start};
  if (start == goal || shortest_route.size() < 2) {
    if (!(start == goal)) islands.push_back(goal);
    return islands;
  }
  double spacing = searchRadius(start, goal, island_count);
  if (max_spacing > 0) spacing = std::min(spacing, max_spacing);
  std::vector<double> along(shortest_route.size(), 0.0);  // route length from S to each cell
  for (std::size_t k = 1; k < shortest_route.size(); ++k)
    along[k] = along[k - 1] + stepLength(directionBetween(shortest_route[k - 1], shortest_route[k]));
  const double total = along.back();
  double last = 0.0;
  for (std::size_t k = 1; k + 1 < shortest_route.size(); ++k) {
    if (total - last <= spacing + 1e-9) break;  // E is within r_s of the last island
    if (along[k] - last < spacing - 1e-9 || !auxiliary.isFree(shortest_route[k])) continue;
    islands.push_back(shortest_route[k]);
    last = along[k];
  }
  islands.push_back(goal);
  return islands;
}

}  // namespace eaci
