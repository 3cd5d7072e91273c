// The exact Pareto front of route length against total turning (issue #30), used by `front`:
// for every turning budget of k 45-degree steps, k = 0..max_steps, the shortest route from start
// to goal whose heading changes between consecutive moves (0..4 steps a corner; the first move
// turns nothing, the goal may be entered in any direction) add up to at most k, kept only when it
// is strictly shorter (by more than 1e-9) than every route kept for a smaller budget, so the
// points come out with turning ascending and length descending and none dominates another.
// Length is the sum of the move lengths (1 straight, sqrt 2 diagonal), the cell costs play no
// part; the moves are the grid's (CostGrid::movesFrom, its corner cutting rule). Computed by a
// Dijkstra over (cell, incoming direction or none at the start, steps turned so far) states,
// written independently of HeadingSearch. Empty when the goal cannot be reached within
// max_steps; start == goal gives the one-cell route of length 0 at k = 0.
#pragma once

#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cost_grid.hpp"

namespace eaci_bench {

struct FrontPoint {
  int turn_steps;      // the budget k: the route turns by exactly k 45-degree steps
  double length;       // cells
  eaci::CellPath path; // start .. goal
};

std::vector<FrontPoint> exactFront(const eaci::CostGrid& grid, eaci::Cell start, eaci::Cell goal, int max_steps);

}  // namespace eaci_bench
