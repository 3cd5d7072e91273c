// Exact shortest paths on the same grid and move rule as the ants: A* and a Dijkstra distance
// field, both the one grid search (grid_search.hpp).
#pragma once

#include <limits>
#include <vector>

#include "eaci/grid/binary_grid.hpp"
#include "eaci/search/grid_search.hpp"

namespace eaci {

struct ShortestPath {
  bool found = false;
  double length = std::numeric_limits<double>::infinity();  // cells
  CellPath path;                                            // start first, goal last
};

// A* from start to goal. Returns found = false when the goal is unreachable or either
// cell is off the map or blocked.
inline ShortestPath shortestPath(const BinaryGrid& grid, Cell start, Cell goal) {
  ShortestPath result;
  if (!grid.isFree(start) || !grid.isFree(goal)) return result;
  GridSearchRequest request;
  request.source = start;
  request.target = goal;
  request.keep_moves = true;
  const GridSearchResult search = searchGrid(grid, request);
  if (!search.reached(goal)) return result;
  result.found = true;
  result.length = search.at(goal);
  result.path = search.routeTo(goal);
  return result;
}

// Dijkstra: grid distance (cells) from `source` to every cell (index order of the grid),
// +infinity where unreachable. The move rule is symmetric, so this is also the distance from
// every cell to `source`.
inline std::vector<double> distanceField(const BinaryGrid& grid, Cell source) {
  GridSearchRequest request;
  request.source = source;
  return searchGrid(grid, request).distance;
}

}  // namespace eaci
