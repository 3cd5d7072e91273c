// The one entry point: plan a route on an occupancy grid with EACI, classic ACO, MAACO
// (re-implemented from public descriptions, not the authors' code) or A*.
// Checks every input and turns each problem into a status and a one-line reason.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "eaci/planner/parameters.hpp"
#include "eaci/aco/pheromone_picture.hpp"
#include "eaci/aco/solvers.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/end_headings.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/metrics/path_metrics.hpp"
#include "eaci/path/smoothing.hpp"
#include "eaci/search/astar.hpp"
#include "eaci/search/heading_search.hpp"
#include "eaci/search/meeting_search.hpp"
#include "eaci/search/reachability.hpp"

namespace eaci {

enum class Algorithm { kEaci, kAco, kMaaco, kAStar };

inline const char* toString(Algorithm a) {
  switch (a) {
    case Algorithm::kEaci: return "eaci";
    case Algorithm::kAco: return "aco";
    case Algorithm::kMaaco: return "maaco";
    case Algorithm::kAStar: return "astar";
  }
  return "?";
}

inline bool parseAlgorithm(const std::string& text, Algorithm& out) {
  if (text == "eaci") out = Algorithm::kEaci;
  else if (text == "aco") out = Algorithm::kAco;
  else if (text == "maaco") out = Algorithm::kMaaco;
  else if (text == "astar") out = Algorithm::kAStar;
  else return false;
  return true;
}

// Why a plan ended as it did, typed where it arises: callers decide from this, never from
// PlanResult::error (a sentence for people).
enum class PlanStatus {
  kSuccess,
  kNoPath,             // start and goal are usable but no route joins them (or no ant reached the goal)
  kStopped,            // should_stop said stop before any route was found (PlanResult::interrupted)
  kStartOffMap,        // the start cell lies off the map
  kStartBlocked,       // the start cell is an obstacle
  kGoalOffMap,         // the goal cell lies off the map
  kGoalBlocked,        // the goal cell is an obstacle
  kInvalidParameters,  // the parameters are refused (validationError), or too large a region for their memory cap
  kInvalidMap,         // the map has no cells, or is larger than a cap
};

// A stable snake_case word ("success", "no_path", ...): the CLI's JSON carries it.
inline const char* toString(PlanStatus status) {
  switch (status) {
    case PlanStatus::kSuccess: return "success";
    case PlanStatus::kNoPath: return "no_path";
    case PlanStatus::kStopped: return "stopped";
    case PlanStatus::kStartOffMap: return "start_off_map";
    case PlanStatus::kStartBlocked: return "start_blocked";
    case PlanStatus::kGoalOffMap: return "goal_off_map";
    case PlanStatus::kGoalBlocked: return "goal_blocked";
    case PlanStatus::kInvalidParameters: return "invalid_parameters";
    case PlanStatus::kInvalidMap: return "invalid_map";
  }
  return "?";
}

// The size caps a plan checks (each refusal is kInvalidMap, or kInvalidParameters for a
// colony's region, with the size and the cap):
// kMaxGridCells (grid/cost_grid.hpp) on the map, kMaxPheromoneBytes (aco/pheromone_field.hpp)
// on a colony's cells, on the whole map or on a geodesic colony's region around the route;
// kMaxHeadingSearchCells (search/heading_search.hpp) on the map for A* with turn_cost > 0.

// What a caller that plans again and again (the ROS node, the move_base plugin, the benchmarks)
// keeps from plan to plan: the exact search's buffers (A*, and the cheapest route geodesic
// islands sit on) and the colony's routes, walkers, worker threads, region and pheromone
// memory. A plan then allocates and clears no whole-map search arrays, starts no threads and
// reuses the memory of its region and pheromone field. One plan at a time per workspace; it
// keeps the largest buffers a plan has needed (destroy it to give the memory back).
struct PlannerWorkspace {
  GridSearchWorkspace astar;    // A*, and the route of geodesic islands on smaller maps
  HeadingSearch turning;        // A* with turn_cost > 0: its open list and open labels
  MeetingSearch meeting;        // the route of geodesic islands from kTwoSidedSearchCells on, and its landmarks
  ColonyWorkspace colony;
};

struct PlanOptions {
  bool record_pheromone = false;   // fill PlanResult::pheromone (strongest edge leaving each cell)
  // The caller's stop check (a deadline, a cancel flag). Called with the number of colony
  // iterations done (0 during set-up), between set-up steps, between iterations, and inside
  // every loop whose work grows with the map or the route (A*, the two sides of the search
  // that meets in the middle, floods, leg fields, region and pheromone building, island scans,
  // ant walks, smoothing) every StopPoll::kWorkBetweenChecks (4096) cells or steps. It may be
  // called from any thread the plan uses, at the same time: it must be thread-safe (an atomic
  // flag, a clock), and cheap. Once it returns true the plan ends promptly with
  // PlanResult::interrupted: the best route so far (colony iterations; a stopped iteration is
  // dropped), or for geodesic EACI the A* route its islands sit on if that search had
  // finished, else kNoPath with an error that says it was stopped. Stopped while smoothing,
  // smoothed_path is smoothed up to there and follows the route's cells after (valid).
  StopCheck should_stop;
  IterationObserver observer;      // sees the field at iteration 0 (initial) and after each update
  // Kept by a caller that plans again and again; null: this call's own buffers and threads.
  PlannerWorkspace* workspace = nullptr;
  // The headings at the route's ends (the robot's yaw, the goal's; grid angles): with
  // turn_cost > 0 every algorithm prices the turn onto the first move and off the last one
  // like a corner (grid/end_headings.hpp). Default: none, the ends turn nothing.
  EndHeadings end_headings;
  // Geodesic EACI: where the colony's best route scores worse (combined_cost) than the cheapest
  // route its islands sit on (its search's: A*'s, or with turn_cost > 0 the heading search's
  // optimum of cost + turn price), return that route instead
  // (PlanResult::route_from_search, colony_combined_cost). Off for the benchmarks, which
  // measure the colony; the ROS planning service turns it on, so a robot never gets a route
  // worse than the one the search already had.
  bool never_worse_than_search = false;
};

// Where a plan's time went, in milliseconds (steady clock): for profiles (the planning
// service's PlanReply::phases), never for decisions.
struct PlanTimes {
  double search = 0.0;     // the exact search; for the colonies, all their set-up (flood, islands, region, pheromone)
  double colony = 0.0;     // the colony's iterations
  double smoothing = 0.0;  // smoothing the route
};

struct PlanResult {
  PlanStatus status = PlanStatus::kInvalidParameters;
  std::string error;               // one line, empty on success
  Algorithm algorithm = Algorithm::kEaci;
  CellPath path;                   // start first, goal last: the 8-connected route the search found
  // With smooth_path: the corners of the smoothed route (start and goal included, joined by
  // straight segments, path/smoothing.hpp); else the same cells as `path`.
  CellPath smoothed_path;
  double smoothed_length = std::numeric_limits<double>::infinity();  // cells, along smoothed_path
  double cost = std::numeric_limits<double>::infinity();    // sum of the move costs (CostGrid::moveCost): L_k
  double length = std::numeric_limits<double>::infinity();  // cells: straight step 1, diagonal sqrt 2
  // cost + turn_cost x the route's heading change in radians, its end turns included
  // (combinedRouteCost with PlanOptions::end_headings): the objective A* minimises when
  // turn_cost > 0; the same as `cost` when turn_cost is 0.
  double combined_cost = std::numeric_limits<double>::infinity();
  // The price of a radian of turning the plan used: turn_cost, or with turn_cost_unit
  // route_cell turn_cost x the cheapest route's average cell cost (planner/turn_cost_unit.hpp).
  double turn_price = 0.0;
  double total_turn_deg = 0.0;
  int iterations_to_converge = 0;  // iteration that first reached the final cost (0 for A*)
  int iterations_run = 0;
  bool stopped_early = false;
  bool interrupted = false;
  // `path` is the cheapest route geodesic EACI's islands sit on (its search's): no ant reached
  // the goal (stopped by should_stop before one arrived, or every ant lost, as on long routes
  // through mazes), so a robot always gets a route when one exists; or, with
  // PlanOptions::never_worse_than_search, the colony's best scored worse (colony_combined_cost).
  bool route_from_search = false;
  // With never_worse_than_search: the combined cost of the colony's best route that the
  // search's route replaced; +infinity when none was replaced.
  double colony_combined_cost = std::numeric_limits<double>::infinity();
  long long lost_ants_total = 0;
  std::vector<int> ants_per_iteration;  // m, fewer where stop_gap ended an iteration after a wave of ants
  std::vector<int> lost_ants_per_iteration;
  // The route quality L_k per iteration: the cost of the best route (the length on a binary map,
  // as on the paper's maps).
  std::vector<double> iteration_best_cost;  // that iteration's best; +infinity where no ant arrived
  std::vector<double> best_cost_so_far;     // the best of this and every earlier iteration
  std::vector<Cell> islands;       // EACI: S, islands, E; ACO and A*: S, E
  std::vector<double> pheromone;   // per cell, row-major, if requested
  PlanTimes times;

  bool success() const { return status == PlanStatus::kSuccess; }
};

namespace detail {

inline std::string describe(Cell c) {
  std::ostringstream s;
  s << "(row " << c.row << ", col " << c.col << ")";
  return s.str();
}

inline PlanResult failure(Algorithm algorithm, PlanStatus status, const std::string& error) {
  PlanResult r;
  r.algorithm = algorithm;
  r.status = status;
  r.error = error;
  return r;
}

// kSuccess when `c` is a usable start (is_start) or goal on this grid, else the status and `error`.
inline PlanStatus endpointStatus(const CostGrid& grid, Cell c, bool is_start, std::string& error) {
  const char* name = is_start ? "start" : "goal";
  std::ostringstream e;
  PlanStatus status = PlanStatus::kSuccess;
  if (!grid.contains(c)) {
    e << name << " " << describe(c) << " is off the map (" << grid.height() << " rows x " << grid.width() << " columns)";
    status = is_start ? PlanStatus::kStartOffMap : PlanStatus::kGoalOffMap;
  } else if (grid.isBlocked(c)) {
    e << name << " " << describe(c) << " is in an obstacle";
    status = is_start ? PlanStatus::kStartBlocked : PlanStatus::kGoalBlocked;
  }
  error = e.str();
  return status;
}

inline void fillFromColony(const CostGrid& grid, const ColonyResult& colony, const PlanOptions& options,
                           PlanResult& r) {
  r.islands = colony.waypoints;
  r.iterations_run = colony.run.iterations_run;
  r.iterations_to_converge = colony.run.best_iteration;
  r.stopped_early = colony.run.stopped_early;
  r.interrupted = colony.run.interrupted;
  r.ants_per_iteration = colony.run.ants_per_iteration;
  r.lost_ants_per_iteration = colony.run.lost_ants_per_iteration;
  for (int lost : r.lost_ants_per_iteration) r.lost_ants_total += lost;
  r.iteration_best_cost = colony.run.iteration_best_cost;
  r.best_cost_so_far = colony.run.best_cost_so_far;
  for (std::uint32_t index : colony.run.best_cells) r.path.push_back(grid.cellAt(index));
  if (options.record_pheromone && colony.pheromone.cellCount() > 0)
    r.pheromone = strongestPheromoneByGridCell(colony.pheromone, colony.region);
}

}  // namespace detail

inline PlanResult plan(const CostGrid& grid, Cell start, Cell goal, Algorithm algorithm, const Parameters& params,
                       const PlanOptions& options = {});

namespace detail {
// turn_cost_unit route_cell: the plan with turns priced at turn_cost x the cost of the average
// cell of the cheapest route from start to goal (A*, turns not priced), that is the plan of
// that price in free cells.
inline PlanResult planInRouteCells(const CostGrid& grid, Cell start, Cell goal, Algorithm algorithm,
                                   const Parameters& params, const PlanOptions& options) {
  const auto search_start = std::chrono::steady_clock::now();
  StopPoll poll(options.should_stop, 0);
  GridSearchWorkspace own_workspace;
  GridSearchWorkspace& workspace = options.workspace ? options.workspace->astar : own_workspace;
  const CheapestPath cheapest = cheapestPath(grid, start, goal, workspace, &poll);
  if (cheapest.stopped) {
    PlanResult stopped = failure(algorithm, PlanStatus::kStopped,
                                 "stopped (should_stop) while measuring the cheapest route's cells (turn_cost_unit route_cell)");
    stopped.interrupted = true;
    return stopped;
  }
  const double measured_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - search_start).count();
  Parameters priced = params;
  // At most validate()'s bound, which turn_cost x M passes only for turn_cost above 1e6 / M.
  priced.turn_cost = std::min(1e6, params.turn_cost * routeCellCost(cheapest.cost, cheapest.length));
  priced.turn_cost_unit = TurnCostUnit::kFreeCell;
  PlanResult r = plan(grid, start, goal, algorithm, priced, options);
  r.times.search += measured_ms;
  return r;
}
}  // namespace detail

// The move cost rule the parameters ask for.
inline CostRule costRule(const Parameters& params) { return CostRule{params.neutral_cost, params.cost_factor}; }

// Plans on `grid` with the move costs of `params` (neutral_cost, cost_factor), whatever rule
// the grid was built with.
inline PlanResult plan(const CostGrid& grid, Cell start, Cell goal, Algorithm algorithm, const Parameters& params,
                       const PlanOptions& options) {
  using detail::failure;
  const std::string parameter_error = validationError(params);
  if (!parameter_error.empty())
    return failure(algorithm, PlanStatus::kInvalidParameters, "invalid parameter: " + parameter_error);
  const CostRule rule = costRule(params);
  if (grid.costRule().neutral_cost != rule.neutral_cost || grid.costRule().cost_factor != rule.cost_factor) {
    CostGrid ruled = grid;
    ruled.setCostRule(rule);
    return plan(ruled, start, goal, algorithm, params, options);
  }
  if (grid.cellCount() == 0) return failure(algorithm, PlanStatus::kInvalidMap, "the map has no cells");
  for (const auto& [cell, is_start] : {std::pair<Cell, bool>{start, true}, {goal, false}}) {
    std::string error;
    const PlanStatus status = detail::endpointStatus(grid, cell, is_start, error);
    if (status != PlanStatus::kSuccess) return failure(algorithm, status, error);
  }
  // Colonies on the whole map (classic ACO, the paper's islands, region_margin 0) keep
  // pheromone for every cell; geodesic EACI only for its region around the route.
  const bool whole_map_colony = algorithm == Algorithm::kAco || algorithm == Algorithm::kMaaco ||
                                params.island_strategy == IslandStrategy::kPaper ||
                                params.region_margin == 0;
  if (algorithm != Algorithm::kAStar && whole_map_colony &&
      grid.cellCount() > kMaxPheromoneBytes / kPheromoneBytesPerCell) {
    std::ostringstream e;
    e << "map of " << grid.width() << " x " << grid.height() << " cells needs "
      << grid.cellCount() * kPheromoneBytesPerCell / (1 << 20) << " MiB of pheromone, over the cap of "
      << kMaxPheromoneBytes / (1 << 20) << " MiB";
    return failure(algorithm, PlanStatus::kInvalidMap, e.str());
  }
  if (algorithm == Algorithm::kAStar && params.turn_cost > 0 && grid.cellCount() > kMaxHeadingSearchCells) {
    std::ostringstream e;
    e << "map of " << grid.width() << " x " << grid.height() << " cells is larger than the heading search's cap of "
      << kMaxHeadingSearchCells << " cells (A* with turn_cost > 0: 8 states per cell, numbered in 32 bits)";
    return failure(algorithm, PlanStatus::kInvalidMap, e.str());
  }

  if (params.turn_cost > 0 && params.turn_cost_unit == TurnCostUnit::kRouteCell && !(start == goal))
    return detail::planInRouteCells(grid, start, goal, algorithm, params, options);

  PlanResult r;
  r.algorithm = algorithm;
  r.turn_price = params.turn_cost;
  if (start == goal) {  // nothing to search: the route is the start cell itself
    r.status = PlanStatus::kSuccess;
    r.path = {start};
    r.smoothed_path = r.path;
    r.cost = 0.0;
    r.combined_cost = 0.0;
    r.length = 0.0;
    r.smoothed_length = 0.0;
    r.islands = {start};
    return r;
  }
  StopPoll poll(options.should_stop, 0);  // this thread's: A*, the flood, smoothing
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point from) {
    return std::chrono::duration<double, std::milli>(Clock::now() - from).count();
  };
  const Clock::time_point solve_start = Clock::now();
  if (algorithm == Algorithm::kAStar && params.turn_cost > 0) {  // the combined objective: (cell, heading) states
    HeadingSearch own_search;
    HeadingSearch& search = options.workspace ? options.workspace->turning : own_search;
    TurningPath cheapest = search.cheapestPath(grid, start, goal, params.turn_cost, &poll, options.end_headings);
    r.path = std::move(cheapest.path);
    r.islands = {start, goal};
    r.interrupted = cheapest.stopped;
    r.times.search = since(solve_start);
  } else if (algorithm == Algorithm::kAStar) {
    GridSearchWorkspace own_workspace;
    GridSearchWorkspace& workspace = options.workspace ? options.workspace->astar : own_workspace;
    const CheapestPath cheapest = cheapestPath(grid, start, goal, workspace, &poll);
    r.path = cheapest.path;
    r.islands = {start, goal};
    r.interrupted = cheapest.stopped;
    r.times.search = since(solve_start);
  } else {
    const auto unreachable = [&] {
      return failure(algorithm, PlanStatus::kNoPath,
                     "goal " + detail::describe(goal) + " cannot be reached from start " + detail::describe(start));
    };
    // Geodesic EACI finds out itself, from the A* route its islands sit on, without a flood of the map.
    const bool geodesic = algorithm == Algorithm::kEaci && params.island_strategy == IslandStrategy::kGeodesic;
    if (!geodesic) {
      const bool reachable = reachableFrom(grid, start, &poll)[grid.index(goal)] != 0;
      if (poll.stopped()) {
        PlanResult stopped = failure(algorithm, PlanStatus::kStopped,
                                     "stopped (should_stop) while finding the cells reachable from the start");
        stopped.interrupted = true;
        return stopped;
      }
      if (!reachable) return unreachable();
    }
    RouteSearchBuffers search_buffers;
    if (options.workspace) search_buffers = {&options.workspace->astar, &options.workspace->meeting,
                                             &options.workspace->turning};
    ColonyWorkspace* colony_workspace = options.workspace ? &options.workspace->colony : nullptr;
    // The set-up ends where the colony shows its initial field (iteration 0).
    std::optional<Clock::time_point> setup_done;
    const IterationObserver observer = [&](int iteration, const PheromoneField& field, const ColonyRegion& region) {
      if (iteration == 0) setup_done = Clock::now();
      if (options.observer) options.observer(iteration, field, region);
    };
    ColonyResult colony =
        algorithm == Algorithm::kEaci
            ? solveEaci(grid, start, goal, params, options.should_stop, observer, search_buffers, colony_workspace,
                        options.end_headings)
        : algorithm == Algorithm::kMaaco
            ? solveMaaco(grid, start, goal, params, options.should_stop, observer, colony_workspace, options.end_headings)
            : solveClassicAco(grid, start, goal, params, options.should_stop, observer, colony_workspace,
                              options.end_headings);
    r.times.search = setup_done ? std::chrono::duration<double, std::milli>(*setup_done - solve_start).count()
                                : since(solve_start);
    r.times.colony = setup_done ? since(*setup_done) : 0.0;
    if (colony.goal_unreachable) return unreachable();
    if (colony.region_too_large) {
      std::ostringstream e;
      e << "the colony's region within region_margin " << params.region_margin << " of the route holds over "
        << kMaxPheromoneCells << " cells, whose pheromone would exceed the cap of " << (kMaxPheromoneBytes >> 20)
        << " MiB (lower region_margin)";
      return failure(algorithm, PlanStatus::kInvalidParameters, e.str());
    }
    const PlanTimes times = r.times;
    detail::fillFromColony(grid, colony, options, r);
    r.times = times;
    if (colony_workspace) {  // their memory serves the next plan
      colony_workspace->region = std::move(colony.region);
      colony_workspace->pheromone = std::move(colony.pheromone);
    }
    if (r.path.empty() && !colony.search_route.empty()) {
      r.path = colony.search_route;
      r.route_from_search = true;
    } else if (options.never_worse_than_search && !colony.search_route.empty()) {
      // Both routes by the objective the colony answers to: cost + turn_cost x turning.
      const double colony_score = combinedRouteCost(grid, r.path, params.turn_cost, options.end_headings);
      if (combinedRouteCost(grid, colony.search_route, params.turn_cost, options.end_headings) < colony_score) {
        r.colony_combined_cost = colony_score;
        r.path = colony.search_route;
        r.route_from_search = true;
      }
    }
  }
  if (r.path.empty()) {
    r.status = r.interrupted ? PlanStatus::kStopped : PlanStatus::kNoPath;
    if (algorithm == Algorithm::kAStar && r.interrupted)
      r.error = "stopped (should_stop) during the A* search, before it reached the goal";
    else if (algorithm == Algorithm::kAStar)
      r.error = "goal " + detail::describe(goal) + " cannot be reached from start " + detail::describe(start);
    else if (r.interrupted && r.iterations_run == 0)
      r.error = "stopped (should_stop) while setting up, before any ant walked";
    else if (r.interrupted)
      r.error = "stopped (should_stop) after " + std::to_string(r.iterations_run) +
                " iterations, before any ant reached the goal";
    else
      r.error = "no ant reached the goal in " + std::to_string(r.iterations_run) + " iterations although a route exists" +
                (algorithm == Algorithm::kEaci && params.island_strategy == IslandStrategy::kPaper
                     ? " (the paper's islands can sit in dead ends; island_strategy=geodesic avoids them)"
                     : "");
    return r;
  }
  r.status = PlanStatus::kSuccess;
  r.cost = routeCost(grid, r.path);
  r.combined_cost = combinedRouteCost(grid, r.path, params.turn_cost, options.end_headings);
  r.length = pathLength(r.path);
  r.total_turn_deg = totalTurnDegrees(r.path);
  const Clock::time_point smoothing_start = Clock::now();
  r.smoothed_path = params.smooth_path ? roundCorners(grid, smoothRoute(grid, r.path, &poll, params.smooth_tolerance,
                                                                   params.turn_cost, options.end_headings),
                                                       params.round_corners, params.smooth_tolerance, &poll,
                                                       params.turn_cost > 0 && options.end_headings.hasGoal())
                                        : r.path;
  r.times.smoothing = since(smoothing_start);
  r.interrupted = r.interrupted || poll.stopped();
  r.smoothed_length = pathLength(r.smoothed_path);
  return r;
}

// The view's interpretation says which cells are obstacles and what the others cost (its
// makers build it from lethal_cost and allow_unknown: CellInterpretation::costmap, the loaders).
inline PlanResult plan(const GridView& view, Cell start, Cell goal, Algorithm algorithm, const Parameters& params,
                       const PlanOptions& options = {}) {
  if (view.empty()) return detail::failure(algorithm, PlanStatus::kInvalidMap, "the map has no cells");
  if (static_cast<std::size_t>(view.width()) * static_cast<std::size_t>(view.height()) > kMaxGridCells)
    return detail::failure(algorithm, PlanStatus::kInvalidMap, gridTooLargeError(view.width(), view.height()));
  return plan(CostGrid::fromView(view, params.allow_corner_cutting, costRule(params)), start, goal, algorithm, params,
              options);
}

}  // namespace eaci
