// Exact cheapest routes on the same grid, move rule and move costs as the ants: A*, the one
// grid search (grid_search.hpp). A* is the reference for a route's cost; on a binary map the
// cost is the length.
#pragma once

#include <limits>
#include <vector>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/moves.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/search/grid_search.hpp"
#include "eaci/search/grid_search_workspace.hpp"
#include "eaci/search/search_request.hpp"

namespace eaci {

struct CheapestPath {
  bool found = false;
  double cost = std::numeric_limits<double>::infinity();    // sum of the move costs (CostGrid::moveCost)
  double length = std::numeric_limits<double>::infinity();  // cells: straight step 1, diagonal sqrt 2
  CellPath path;                                            // start first, goal last
  bool stopped = false;  // ended by the stop check before the goal was settled (found = false)
};

// A* from start to goal: a cheapest route (on a binary map, a shortest one). Returns found =
// false when the goal is unreachable or either cell is off the map or blocked. `workspace`
// keeps the search's buffers for the next call (same answers with or without it). `stop`:
// ticked once per cell taken off the open list (GridSearchRequest::stop); stopped, the result
// has found = false and stopped = true.
inline CheapestPath cheapestPath(const CostGrid& grid, Cell start, Cell goal, GridSearchWorkspace& workspace,
                                 StopPoll* stop = nullptr) {
  CheapestPath result;
  if (!grid.isFree(start) || !grid.isFree(goal)) return result;
  GridSearchRequest request;
  request.source = start;
  request.target = goal;
  request.keep_moves = true;
  request.stop = stop;
  workspace.search(grid, request);
  result.stopped = workspace.stopped();
  if (result.stopped || !workspace.reached(goal)) return result;
  result.found = true;
  result.cost = workspace.at(goal);
  result.path = workspace.routeTo(goal);
  result.length = pathLength(result.path);
  return result;
}

inline CheapestPath cheapestPath(const CostGrid& grid, Cell start, Cell goal) {
  GridSearchWorkspace workspace;
  return cheapestPath(grid, start, goal, workspace);
}

}  // namespace eaci
