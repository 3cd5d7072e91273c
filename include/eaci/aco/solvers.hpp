// EACI (Section 4) and the classic ACO baseline (Section 3) on a CostGrid.
// Both expect validated parameters and free, mutually reachable, distinct S and E;
// eaci::plan() checks all of that before it calls them.
#pragma once

#include <utility>
#include <vector>

#include "eaci/aco/auxiliary_map.hpp"
#include "eaci/aco/colony.hpp"
#include "eaci/aco/geodesic_islands.hpp"
#include "eaci/aco/initial_pheromone.hpp"
#include "eaci/aco/islands.hpp"
#include "eaci/grid/reachability.hpp"
#include "eaci/search/astar.hpp"

namespace eaci {

struct ColonyResult {
  std::vector<Cell> waypoints;  // EACI: the islands L_1 = S .. L_N = E; ACO: S, E
  ColonyRun run;
  PheromoneField pheromone;     // the field after the last iteration
};

struct IslandPlan {
  std::vector<Cell> islands;                   // L_1 = S, ..., L_N = E
  std::vector<LegDistanceField> leg_distance;  // empty: the paper's straight-line d_jg
};

// Islands for the chosen strategy, both from the auxiliary map (Eq. 12):
// kPaper: Eq. 13-15; kGeodesic: r_s apart (at most island_spacing_max) on a cheapest route,
// with exact leg costs.
inline IslandPlan planIslands(const CostGrid& grid, Cell start, Cell goal, const Parameters& params) {
  const CostGrid aux = auxiliaryMap(grid, start, goal);
  if (params.island_strategy == IslandStrategy::kPaper)
    return {paperIslands(aux, reachableFrom(grid, start), start, goal, params.islands), {}};
  const CellPath route = descendCostField(grid, costField(grid, goal), start);
  IslandPlan plan{geodesicIslands(aux, route, start, goal, params.islands, params.island_spacing_max), {}};
  plan.leg_distance = legDistanceFields(grid, route, plan.islands);
  return plan;
}

// Steps 1-7: auxiliary map and islands (by params.island_strategy), non-uniform initial pheromone, ants walking leg by
// leg with the turning-aware heuristic, adaptive update. `should_stop` is also asked between
// the set-up steps (which take a fifth of a second on an 800 x 800 map); stopped there, the
// result has no route and an empty pheromone field.
inline ColonyResult solveEaci(const CostGrid& grid, Cell start, Cell goal, const Parameters& params,
                              const StopCheck& should_stop = {}, const IterationObserver& observer = {}) {
  ColonyResult result;
  const auto stopped_in_setup = [&] {
    if (should_stop && should_stop(0)) result.run.interrupted = true;
    return result.run.interrupted;
  };
  IslandPlan islands = planIslands(grid, start, goal, params);
  result.waypoints = islands.islands;
  if (stopped_in_setup()) return result;
  result.pheromone = initialIslandPheromone(grid, result.waypoints, params.lambda, params.alpha);
  if (stopped_in_setup()) return result;
  if (observer) observer(0, result.pheromone);
  const WalkSetup setup(grid, result.pheromone, result.waypoints, HeuristicRule::kTurningAware, params.beta,
                        params.epsilon, std::move(islands.leg_distance));
  Colony colony(setup, result.pheromone, params, UpdateRule::kAdaptive, euclidean(start, goal));
  result.run = colony.run(should_stop, observer);
  return result;
}

// Classic ACO (Eq. 8-11): uniform initial pheromone aco_tau0, heuristic 1/d_jg, evaporation aco_rho.
inline ColonyResult solveClassicAco(const CostGrid& grid, Cell start, Cell goal, const Parameters& params,
                                    const StopCheck& should_stop = {}, const IterationObserver& observer = {}) {
  ColonyResult result;
  result.waypoints = {start, goal};
  result.pheromone = PheromoneField(grid.cellCount(), params.aco_tau0, params.alpha);
  if (observer) observer(0, result.pheromone);
  const WalkSetup setup(grid, result.pheromone, result.waypoints, HeuristicRule::kGoalDistance, params.beta,
                        params.epsilon);
  Colony colony(setup, result.pheromone, params, UpdateRule::kClassic, euclidean(start, goal));
  result.run = colony.run(should_stop, observer);
  return result;
}

}  // namespace eaci
