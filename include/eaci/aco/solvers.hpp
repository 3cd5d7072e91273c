// EACI (Section 4), the classic ACO baseline (Section 3) and MAACO (re-implemented from public
// descriptions, not the authors' code) on a CostGrid: each sets up its waypoints, region and
// initial pheromone and runs the colony with its rules (variants.hpp).
// Both expect validated parameters and free, mutually reachable, distinct S and E;
// eaci::plan() checks all of that before it calls them.
#pragma once

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "eaci/aco/auxiliary_map.hpp"
#include "eaci/aco/colony.hpp"
#include "eaci/aco/colony_region.hpp"
#include "eaci/aco/elliptical_pheromone.hpp"
#include "eaci/aco/geodesic_islands.hpp"
#include "eaci/aco/initial_pheromone.hpp"
#include "eaci/aco/islands.hpp"
#include "eaci/search/reachability.hpp"
#include "eaci/search/astar.hpp"
#include "eaci/search/heading_search.hpp"
#include "eaci/search/meeting_search.hpp"

namespace eaci {

struct ColonyResult {
  std::vector<Cell> waypoints;  // EACI: the islands L_1 = S .. L_N = E; ACO: S, E
  bool goal_unreachable = false;  // geodesic EACI: no route from S to E (nothing else was done)
  CellPath search_route;          // geodesic EACI: the cheapest route (A*) its islands sit on
  ColonyRun run;
  ColonyRegion region;          // the cells the ants walked on
  PheromoneField pheromone;     // the field after the last iteration, per cell of `region`
  // Geodesic EACI: the region within region_margin of the route would hold more than
  // kMaxPheromoneCells cells (its pheromone more than kMaxPheromoneBytes); no colony was made.
  bool region_too_large = false;
};

struct IslandPlan {
  std::vector<Cell> islands;                   // L_1 = S, ..., L_N = E
  std::vector<LegCostField> leg_cost;  // empty: the paper's straight-line d_jg
  CellPath route;                              // geodesic: the cheapest route S .. E the islands are on
  // its cost (CostGrid::moveCost); with turn_cost > 0 its combined cost (combinedRouteCost)
  double route_cost = std::numeric_limits<double>::infinity();
};

// The exact searches' buffers a caller keeps between plans (any may be null: the call's own).
struct RouteSearchBuffers {
  GridSearchWorkspace* astar = nullptr;  // A* on maps under kTwoSidedSearchCells
  MeetingSearch* meeting = nullptr;      // the search that meets in the middle from there on
  HeadingSearch* turning = nullptr;      // the (cell, heading) search, turn_cost > 0
};

// Geodesic islands find their route with the search that meets in the middle
// (MeetingSearch::cheapestRoute) on maps of at least this many cells (256 x 256):
// its two sides run at the same time with threads != 1, where one A* cannot use a second core.
// On smaller maps one A* takes a millisecond or two, and the paper's maps keep the routes,
// and so the tables, they had (of equally short routes the two searches may pick different ones).
constexpr std::size_t kTwoSidedSearchCells = std::size_t{256} * 256;

// Islands for the chosen strategy, both from the auxiliary map (Eq. 12):
// kPaper: Eq. 13-15; kGeodesic: r_s apart (at most island_spacing_max) on a cheapest route
// (A*), with exact leg costs. Geodesic islands only ask Eq. 12 about cells of the route, so
// they never build the auxiliary map. With turn_cost > 0 the route is a cheapest one under the
// combined objective (HeadingSearch), the one the colony scores (issue #30).
// `buffers`: the exact searches' buffers, kept by the caller between plans.
// `stop`: ticked by every step's loops (auxiliary map, flood, island scan, the search, the leg
// fields); once it says stop the plan is unfinished (the caller reads stop->stopped()): a
// geodesic plan keeps its route when the search had finished. `ends`: the headings at the
// route's ends, priced with turn_cost (grid/end_headings.hpp).
inline IslandPlan planIslands(const CostGrid& grid, Cell start, Cell goal, const ColonyParameters& params,
                              const RouteSearchBuffers& buffers = {}, StopPoll* stop = nullptr,
                              const EndHeadings& ends = {}) {
  if (params.island_strategy == IslandStrategy::kPaper) {
    const CostGrid auxiliary = auxiliaryMap(grid, start, goal, AuxiliaryBorder::kFree, stop);
    if (stop != nullptr && stop->stopped()) return {};
    const std::vector<std::uint8_t> reachable = reachableFrom(grid, start, stop);
    if (stop != nullptr && stop->stopped()) return {};
    return {paperIslands(auxiliary, reachable, start, goal, params.islands, stop), {}, {}};
  }
  IslandPlan plan;
  if (params.turn_cost > 0 && grid.cellCount() <= kMaxHeadingSearchCells) {
    HeadingSearch own_search;
    TurningPath cheapest = (buffers.turning ? *buffers.turning : own_search)
                               .cheapestPath(grid, start, goal, params.turn_cost, stop, ends);
    plan.route = std::move(cheapest.path);
    plan.route_cost = cheapest.combined_cost;
  } else if (grid.cellCount() >= kTwoSidedSearchCells) {
    MeetingSearch own_search;
    MeetingSearch& search = buffers.meeting ? *buffers.meeting : own_search;
    plan.route = search.cheapestRoute(grid, start, goal, resolveThreadCount(params.threads), &plan.route_cost, stop);
  } else {
    GridSearchWorkspace own_workspace;
    CheapestPath cheapest = cheapestPath(grid, start, goal, buffers.astar ? *buffers.astar : own_workspace, stop);
    plan.route = std::move(cheapest.path);
    plan.route_cost = cheapest.cost;
  }
  if (plan.route.empty()) return plan;
  plan.islands = geodesicIslands([&](Cell c) { return freeOnAuxiliaryMap(grid, c, start, goal); }, plan.route, start,
                                 goal, params.islands, params.island_spacing_max);
  plan.leg_cost = legCostFields(grid, plan.route, plan.islands, stop);
  return plan;
}

// The cells the colony works on: geodesic islands with region_margin > 0, the cells within that
// many moves of the route (none, tooLarge(), beyond kMaxPheromoneCells); otherwise the whole
// map (eaci::plan has checked its size). `reuse`: a region whose memory the new one takes
// over. `stop`: as ColonyRegion's.
inline ColonyRegion colonyRegion(const CostGrid& grid, const IslandPlan& islands, const ColonyParameters& params,
                                 ColonyRegion reuse = {}, StopPoll* stop = nullptr) {
  if (params.island_strategy == IslandStrategy::kGeodesic && params.region_margin > 0)
    return ColonyRegion::aroundRoute(grid, islands.route, params.region_margin, std::move(reuse), kMaxPheromoneCells,
                                     stop);
  return ColonyRegion::wholeMap(grid, std::move(reuse), stop);
}

// Steps 1-7: auxiliary map and islands (by params.island_strategy), non-uniform initial pheromone, ants walking leg by
// leg with the turning-aware heuristic, adaptive update. `should_stop` is also asked between
// the set-up steps and every few thousand cells inside them (StopPoll); stopped there, the
// result has no colony route and an empty pheromone field (geodesic islands: search_route is
// the route when the search had finished).
// `search_buffers`, `colony_workspace`: buffers and threads kept by the caller between plans
// (null: this call's own). The result's region and pheromone field hold the colony
// workspace's memory; a caller that keeps the workspace hands them back to it when done.
// `ends`: the headings at the route's ends, priced with turn_cost (grid/end_headings.hpp).
inline ColonyResult solveEaci(const CostGrid& grid, Cell start, Cell goal, const ColonyParameters& params,
                              const StopCheck& should_stop = {}, const IterationObserver& observer = {},
                              const RouteSearchBuffers& search_buffers = {},
                              ColonyWorkspace* colony_workspace = nullptr, const EndHeadings& ends = {}) {
  ColonyResult result;
  StopPoll setup_poll(should_stop, 0);  // one counter through all the set-up steps
  const auto stopped_in_setup = [&] {
    if (setup_poll.stopped() || setup_poll.askNow()) result.run.interrupted = true;
    return result.run.interrupted;
  };
  IslandPlan islands = planIslands(grid, start, goal, params, search_buffers, &setup_poll, ends);
  if (setup_poll.stopped()) {  // geodesic: the search's route if it had finished (else empty)
    result.run.interrupted = true;
    if (!islands.route.empty()) {
      result.waypoints = islands.islands;
      result.search_route = islands.route;
    }
    return result;
  }
  if (params.island_strategy == IslandStrategy::kGeodesic && islands.route.empty()) {
    result.goal_unreachable = true;
    return result;
  }
  result.waypoints = islands.islands;
  result.search_route = islands.route;
  if (stopped_in_setup()) return result;
  ColonyRegion region = colonyRegion(grid, islands, params,
                                     colony_workspace ? std::move(colony_workspace->region) : ColonyRegion{}, &setup_poll);
  if (region.tooLarge()) {
    result.region_too_large = true;
    return result;
  }
  if (stopped_in_setup()) return result;
  result.pheromone =
      initialIslandPheromone(grid, region, result.waypoints, params.lambda, params.alpha,
                             colony_workspace ? std::move(colony_workspace->pheromone) : PheromoneField{}, &setup_poll);
  if (stopped_in_setup()) {
    result.pheromone = PheromoneField{};
    return result;
  }
  WalkSetup setup(grid, std::move(region), result.pheromone, result.waypoints, HeuristicRule::kTurningAware,
                  params.beta, params.epsilon, std::move(islands.leg_cost));
  setup.priceTurns(params.turn_cost, ends);
  if (!islands.route.empty()) setup.setExitDirections(islands.route);
  if (observer) observer(0, result.pheromone, setup.region);
  Colony<EaciRules> colony(setup, result.pheromone, params, EaciRules(params, euclidean(start, goal)),
                           islands.route_cost, colony_workspace);
  result.run = colony.run(should_stop, observer);
  result.region = std::move(setup.region);
  return result;
}

// The colonies on the whole map with waypoints S and E (classic ACO, MAACO): the region, the
// initial pheromone `initial(region, reuse, poll)` (poll: stopped, the run is interrupted),
// the walk with `rules`. `colony_workspace` and `ends` as for solveEaci.
template <class Rules, class InitialPheromone>
ColonyResult solveOnWholeMap(const CostGrid& grid, Cell start, Cell goal, const ColonyParameters& params, Rules rules,
                             const InitialPheromone& initial, const StopCheck& should_stop,
                             const IterationObserver& observer, ColonyWorkspace* colony_workspace,
                             const EndHeadings& ends) {
  ColonyResult result;
  result.waypoints = {start, goal};
  StopPoll setup_poll(should_stop, 0);
  ColonyRegion region =
      ColonyRegion::wholeMap(grid, colony_workspace ? std::move(colony_workspace->region) : ColonyRegion{}, &setup_poll);
  if (!setup_poll.stopped())
    result.pheromone = initial(region, colony_workspace ? std::move(colony_workspace->pheromone) : PheromoneField{},
                               setup_poll);
  if (setup_poll.stopped()) {  // the colony asks again before its first iteration
    result.run.interrupted = true;
    result.pheromone = PheromoneField{};
    return result;
  }
  WalkSetup setup(grid, std::move(region), result.pheromone, result.waypoints, HeuristicRule::kGoalDistance,
                  params.beta, params.epsilon);
  setup.priceTurns(params.turn_cost, ends);
  if (observer) observer(0, result.pheromone, setup.region);
  Colony<Rules> colony(setup, result.pheromone, params, std::move(rules), std::numeric_limits<double>::infinity(),
                       colony_workspace);
  result.run = colony.run(should_stop, observer);
  result.region = std::move(setup.region);
  return result;
}

// Classic ACO (Eq. 8-11): uniform initial pheromone aco_tau0, heuristic 1/d_jg, evaporation aco_rho.
inline ColonyResult solveClassicAco(const CostGrid& grid, Cell start, Cell goal, const ColonyParameters& params,
                                    const StopCheck& should_stop = {}, const IterationObserver& observer = {},
                                    ColonyWorkspace* colony_workspace = nullptr, const EndHeadings& ends = {}) {
  const auto uniform = [&](const ColonyRegion&, PheromoneField field, StopPoll&) {
    field.reset(grid.cellCount(), params.aco_tau0, params.alpha);
    return field;
  };
  return solveOnWholeMap(grid, start, goal, params, ClassicAcoRules(params), uniform, should_stop, observer,
                         colony_workspace, ends);
}

// MAACO (re-implemented from public descriptions, not the authors' code; docs/algorithm.md):
// elliptical initial pheromone (C = maaco_tau0), pheromone weight maaco_alpha, MaacoRules.
inline ColonyResult solveMaaco(const CostGrid& grid, Cell start, Cell goal, const ColonyParameters& params,
                               const StopCheck& should_stop = {}, const IterationObserver& observer = {},
                               ColonyWorkspace* colony_workspace = nullptr, const EndHeadings& ends = {}) {
  const auto elliptical = [&](const ColonyRegion& region, PheromoneField field, StopPoll& poll) {
    return ellipticalInitialPheromone(grid, region, start, goal, params.maaco_tau0, params.maaco_alpha,
                                      std::move(field), &poll);
  };
  return solveOnWholeMap(grid, start, goal, params, MaacoRules(params, start, goal, std::max(grid.width(), grid.height())),
                         elliptical, should_stop, observer, colony_workspace, ends);
}

}  // namespace eaci
