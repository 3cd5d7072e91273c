// One ant's walk from S to E through the waypoints (Eq. 8), shared by every colony
// (aco/variants.hpp): classic ACO and MAACO (waypoints S, E), EACI (waypoints = islands). Its
// rules (candidate moves, heuristic, transition) are the variant's.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "eaci/aco/ant_route.hpp"
#include "eaci/aco/candidate_moves.hpp"
#include "eaci/aco/colony_region.hpp"
#include "eaci/aco/heuristic.hpp"
#include "eaci/aco/leg_cost_field.hpp"
#include "eaci/aco/pheromone_field.hpp"
#include "eaci/aco/transition.hpp"
#include "eaci/random.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/end_headings.hpp"

namespace eaci {

enum class HeuristicRule {
  kGoalDistance,  // Eq. 9, classic ACO
  kTurningAware,  // Eq. 16-17, EACI
};

// eta^beta for eta = 1 / x: x^-beta, by a fixed chain of multiplications when beta is a small
// whole number (the paper's 7), else by pow().
class InversePower {
 public:
  explicit InversePower(double beta) : beta_(beta) {
    if (beta >= 0 && beta <= 12 && beta == std::floor(beta)) whole_ = static_cast<int>(beta);
  }
  double operator()(double x) const {
    double y = x;
    applyInPlace(&y, 1);
    return y;
  }

  // x[k] <- x[k]^-beta for k < n; the dispatch on beta sits outside the loop so the loop
  // body is straight-line arithmetic the compiler can vectorise.
  void applyInPlace(double* x, int n) const {
    switch (whole_) {
      case 0: fill(x, n); break;
      case 1: apply<1>(x, n); break;
      case 2: apply<2>(x, n); break;
      case 3: apply<3>(x, n); break;
      case 4: apply<4>(x, n); break;
      case 5: apply<5>(x, n); break;
      case 6: apply<6>(x, n); break;
      case 7: apply<7>(x, n); break;
      case 8: apply<8>(x, n); break;
      case 9: apply<9>(x, n); break;
      case 10: apply<10>(x, n); break;
      case 11: apply<11>(x, n); break;
      case 12: apply<12>(x, n); break;
      default:
        for (int k = 0; k < n; ++k) x[k] = std::pow(x[k], -beta_);
    }
  }

 private:
  static void fill(double* x, int n) {
    for (int k = 0; k < n; ++k) x[k] = 1.0;
  }
  template <int N>
  static void apply(double* x, int n) {
    for (int k = 0; k < n; ++k) x[k] = 1.0 / power<N>(x[k]);
  }
  // x^N by squaring: depth ceil(log2 N) + popcount(N) - 1 multiplications.
  template <int N>
  static double power(double x) {
    if constexpr (N == 1) return x;
    else if constexpr (N % 2 == 0) { const double h = power<N / 2>(x); return h * h; }
    else return x * power<N - 1>(x);
  }

  double beta_;
  int whole_ = -1;
};

// Everything an ant reads; shared by all ants of an iteration and never written during it.
// Cells are numbered by `region` (ColonyRegion): the pheromone, the waypoint marks and the
// distance tables are per region cell.
struct WalkSetup {
  const CostGrid* grid = nullptr;
  const PheromoneField* pheromone = nullptr;
  ColonyRegion region;                        // the cells the ants may walk on
  std::vector<Cell> waypoints;                // L_1 = S, ..., L_N = E
  std::vector<std::int32_t> waypoint_of_cell;  // per region cell: its index in `waypoints`, or -1
  // d_jg of the heuristic: empty -> Euclidean distance to the leg's goal (the paper);
  // else leg_cost[z] is the route cost to waypoint z (geodesic islands).
  std::vector<LegCostField> leg_cost;
  HeuristicRule heuristic = HeuristicRule::kGoalDistance;
  InversePower eta_power{7.0};                // x -> x^-beta
  // sigma of Eq. 17 by [previous direction + 1][direction], plus the price of the turn when
  // turns are priced (priceTurns); row 0: no previous move, sigma = 0 (plus, with a start
  // heading, the first move's turn from it).
  std::array<std::array<double, kDirections>, kDirections + 1> turning_cost{};
  // The price of a turn of k 45-degree steps, turn_cost x k x pi/4 (issue #30), which each move
  // adds to the route's cost L_k; all 0 unless priceTurns was called with turn_cost > 0.
  std::array<double, 5> turn_price{};
  bool prices_turns = false;
  // The first move's price by direction: its turn from the start heading (EndHeadings), 0 without one.
  std::array<double, kDirections> start_turn_price{};
  // Per waypoint, by the direction a route enters it in: the price of turning onto the way it
  // leaves, an island's exit direction (setExitDirections) or the goal heading (priceTurns);
  // 0 where unknown. Read only when turns are priced.
  std::vector<std::array<double, kDirections>> leave_price;
  // d_jg (costToWaypoint) tabulated per waypoint over the region (filled by
  // tabulateCostsToWaypoints() when it fits): one load per candidate instead of a computation.
  std::vector<std::vector<float>> cost_to_waypoint_table;
  static constexpr std::size_t kMaxCostTableEntries = std::size_t{1} << 22;  // 16 MiB of floats
  // Leg costs are tabulated only up to this many entries per region cell (64 bytes, under
  // half the pheromone's): a table of region cells x islands grows with the square of the
  // route's length, and memory and set-up should grow with the route.
  static constexpr std::size_t kMaxLegTableEntriesPerCell = 16;

  // Ants on the whole map.
  WalkSetup(const CostGrid& g, const PheromoneField& field, std::vector<Cell> points, HeuristicRule rule,
            double beta, double epsilon, std::vector<LegCostField> leg_costs = {})
      : WalkSetup(g, ColonyRegion::wholeMap(g), field, std::move(points), rule, beta, epsilon,
                  std::move(leg_costs)) {}

  // Ants on `cells` (which must hold every waypoint; `field` is indexed by its cells).
  WalkSetup(const CostGrid& g, ColonyRegion cells, const PheromoneField& field, std::vector<Cell> points,
            HeuristicRule rule, double beta, double epsilon, std::vector<LegCostField> leg_costs = {})
      : grid(&g), pheromone(&field), region(std::move(cells)), waypoints(std::move(points)),
        waypoint_of_cell(region.size(), -1), leg_cost(std::move(leg_costs)), heuristic(rule),
        eta_power(beta) {
    for (std::size_t w = 0; w < waypoints.size(); ++w)
      waypoint_of_cell[region.regionIndex(waypoints[w])] = static_cast<std::int32_t>(w);
    if (rule == HeuristicRule::kTurningAware)
      for (int from = 0; from < kDirections; ++from)
        for (int to = 0; to < kDirections; ++to) turning_cost[from + 1][to] = turningCost(from, to, epsilon);
    tabulateCostsToWaypoints();
  }

  // Prices turning (issue #30): with turn_cost > 0 every route's L_k is its combined cost (the
  // move costs plus turn_cost x its heading change in radians, combinedRouteCost), and the
  // heuristic's d_jg + sigma counts the candidate move's turn at that price too, so the walk,
  // the update and the ranking of routes score one objective. With end headings the first move
  // and the arrival at E are priced the same way (combinedRouteCost with `ends`). turn_cost 0
  // changes nothing.
  void priceTurns(double turn_cost, const EndHeadings& ends = {}) {
    if (!(turn_cost > 0)) return;
    prices_turns = true;
    for (int k = 0; k <= 4; ++k) turn_price[k] = turn_cost * k * kTurnStepRadians;
    for (int from = 0; from < kDirections; ++from)
      for (int to = 0; to < kDirections; ++to) turning_cost[from + 1][to] += turn_price[turnSteps(from, to)];
    start_turn_price = headingTurnPrices(ends.start, turn_cost);
    for (int to = 0; to < kDirections; ++to) turning_cost[0][to] += start_turn_price[to];
    leave_price.assign(waypoints.size(), std::array<double, kDirections>{});
    leave_price.back() = headingTurnPrices(ends.goal, turn_cost);
  }

  // The direction the route `route` (S .. E, through every waypoint in order, as geodesic
  // islands are) leaves each waypoint in; the heuristic then prices the turn at a leg's end.
  // After priceTurns.
  void setExitDirections(const CellPath& route) {
    if (!prices_turns) return;
    std::size_t z = 0;
    for (std::size_t k = 0; k + 1 < route.size() && z + 1 < waypoints.size(); ++k)
      if (route[k] == waypoints[z]) {
        const int exit = directionBetween(route[k], route[k + 1]);
        for (int in = 0; in < kDirections; ++in) leave_price[z][in] = turn_price[turnSteps(in, exit)];
        ++z;
      }
  }

  // With turns priced, the turns a move into `to` in direction `dir` commits the ant to at its
  // leg's end: entering the leg's goal `target` and turning onto the way it leaves (its exit
  // direction, or at E the goal heading: leave_price). From `to` itself or a neighbour of it the
  // leg's last step is known, and the price is exact; from farther, the least turning any route
  // heading `dir` needs to reach the goal (turnStepsAtLeast) or to turn onto the way it leaves
  // (no route turns less than the angle between its first and last headings), whichever is
  // more, so that a move that carries the ant straight past its island is priced for the way back.
  double legEndTurnPrice(Cell to, std::size_t target, int dir) const {
    const Cell island = waypoints[target];
    const std::array<double, kDirections>& leave = leave_price[target];
    if (to == island) return leave[dir];
    const int last = directionBetween(to, island);
    if (last < 0)
      return std::max(turn_price[turnStepsAtLeast(dir, island.row - to.row, island.col - to.col)], leave[dir]);
    return turn_price[turnSteps(dir, last)] + leave[last];
  }

  // d_jg: what reaching waypoint `target` from `next` costs: the leg's exact route cost
  // (geodesic islands), else the straight-line distance (the paper's; a lower bound of it).
  double costToWaypoint(Cell next, std::size_t target) const {
    if (!leg_cost.empty()) return leg_cost[target].at(next);
    const Cell goal = waypoints[target];
    return std::hypot(next.row - goal.row, next.col - goal.col);
  }

  // Fills cost_to_waypoint_table once the waypoints and leg costs are set, if it fits.
  void tabulateCostsToWaypoints() {
    cost_to_waypoint_table.clear();
    const std::size_t entries = region.size() * (waypoints.size() - 1);
    if (entries > kMaxCostTableEntries) return;
    if (!leg_cost.empty() && entries > kMaxLegTableEntriesPerCell * region.size()) return;
    cost_to_waypoint_table.resize(waypoints.size());
    for (std::size_t z = 1; z < waypoints.size(); ++z) {
      cost_to_waypoint_table[z].resize(region.size());
      for (std::uint32_t r = 0; r < region.size(); ++r)
        cost_to_waypoint_table[z][r] = static_cast<float>(costToWaypoint(grid->cellAt(region.gridIndex(r)), z));
    }
  }

  // d_jg + sigma, the quantity Eq. 9 (sigma = 0) and Eq. 16-17 invert, for the move in
  // direction `dir` from cell `from` into region cell `next`.
  // With leg costs (geodesic islands) d_jg also counts what entering j costs beyond the move's
  // length, so that the ant sees the cost of the cell it steps on: d_jg + sigma is then the
  // cost of the cheapest route through j, less the move's length. On a binary map that excess
  // is 0 and d_jg is the leg distance.
  double heuristicDistance(Cell from, std::uint32_t next, std::size_t target, int previous_dir, int dir) const {
    const double sigma = turning_cost[previous_dir + 1][dir];
    const Cell to = step(from, dir);
    double distance =
        cost_to_waypoint_table.empty() ? costToWaypoint(to, target) : cost_to_waypoint_table[target][next];
    if (!leg_cost.empty()) distance += grid->moveCostInto(grid->index(to), dir) - stepLength(dir);
    if (prices_turns) distance += legEndTurnPrice(to, target, dir);
    return distance + sigma;
  }

  // eta_ij^beta of Eq. 9 or Eq. 16-17, (d_jg + sigma)^-beta, for the allowed move in direction
  // `dir` from cell `from` (region cell `from_cell`).
  double heuristicWeight(Cell from, std::uint32_t from_cell, std::size_t target, int previous_dir, int dir) const {
    return eta_power(heuristicDistance(from, region.neighbour(from_cell, dir), target, previous_dir, dir));
  }
};

// The walk rules of classic ACO and EACI (Eq. 8 with Eq. 9 or Eq. 16-17): every open move is a
// candidate, eta = 1 / (d_jg + sigma) (WalkSetup::heuristicDistance), roulette wheel, and the
// leg's goal taken at once when it is an open neighbour (the d = 0 guard of Eq. 9).
struct WaypointHeuristic {
  double operator()(const WalkSetup& setup, double /*walked_to_here*/, Cell here, std::uint32_t next,
                    std::size_t target, int previous_dir, int dir) const {
    return setup.heuristicDistance(here, next, target, previous_dir, dir);
  }
};
struct WaypointWalk {
  AllowedMoves candidates;
  WaypointHeuristic heuristic;
  RouletteTransition transition;
  static constexpr bool kTakeGoalWhenNeighbour = true;
};

// Walks ants one after the other, reusing its memory: nothing is allocated during a walk
// once the route's vectors have grown to the longest route seen.
class AntWalker {
 public:
  // The ant's taboo list spans the whole route (spec 3.5): it never enters a cell twice.
  // It may not step on an island other than the one it is heading for, so the route visits
  // the islands in order. `Rules` (WaypointWalk, aco/variants.hpp) name the candidate moves,
  // the heuristic, the transition and whether the leg's goal is taken at once when it is an
  // open neighbour. An ant with no candidate is lost: route.complete = false.
  // `stop`: ticked once per step (a walk may take as many steps as the region has cells); once
  // it says stop the walk ends there, incomplete.
  template <class Rules>
  void walk(const WalkSetup& setup, const Rules& rules, SplitMix64& rng, AntRoute& route, StopPoll* stop = nullptr) {
    const CostGrid& grid = *setup.grid;
    const ColonyRegion& region = setup.region;
    beginWalk(region.size());
    Cell here = setup.waypoints.front();
    std::uint32_t current = region.regionIndex(here);
    route.reset(current);
    visit(current);
    std::size_t target = 1;
    int previous_dir = -1;
    std::array<std::uint32_t, kDirections> neighbour{};
    constexpr bool every_open_move = decltype(rules.candidates)::kEveryOpenMove;
    while (target < setup.waypoints.size()) {
      if (stop != nullptr && stop->tick()) return;
      int chosen = -1;
      std::uint32_t chosen_cell = ColonyRegion::kNone;
      const std::uint8_t allowed = region.moves(current);
      // Eq. 8 numerator tau^alpha * eta^beta, in three passes: the candidates' heuristic
      // distances (as the open moves are found, when every open move is a candidate), raised
      // to -beta together, multiplied by their pheromone.
      int count = 0;
      unsigned open = 0;  // free, untabooed, onto no island but this leg's goal
      const auto add_candidate = [&](int d, std::uint32_t j) {
        candidate_dirs_[count] = d;
        candidate_cells_[count] = j;
        candidate_weights_[count] = rules.heuristic(setup, route.length, here, j, target, previous_dir, d);
        ++count;
      };
      for (int d = 0; d < kDirections; ++d) {
        if (!(allowed & (1u << d))) continue;
        const std::uint32_t j = region.neighbourAlong(current, d);
        if (visited(j)) continue;
        const std::int32_t waypoint = setup.waypoint_of_cell[j];
        if (waypoint == static_cast<std::int32_t>(target) && Rules::kTakeGoalWhenNeighbour) {
          chosen = d;  // the goal of this leg is a neighbour: take it
          chosen_cell = j;
          break;
        }
        if (waypoint >= 0 && waypoint != static_cast<std::int32_t>(target)) continue;  // another island
        if constexpr (every_open_move) {
          add_candidate(d, j);
        } else {
          open |= 1u << d;
          neighbour[d] = j;
        }
      }
      if (chosen < 0) {
        if constexpr (!every_open_move)
          for (unsigned candidates = rules.candidates(open, here); candidates != 0; candidates &= candidates - 1)
            add_candidate(__builtin_ctz(candidates), neighbour[__builtin_ctz(candidates)]);
        if (count == 0) return;  // deadlock: a lost ant
        setup.eta_power.applyInPlace(candidate_weights_.data(), count);
        double total = 0.0;
        for (int k = 0; k < count; ++k) {
          candidate_weights_[k] *= setup.pheromone->weight(current, candidate_dirs_[k]);
          total += candidate_weights_[k];
        }
        const int k = rules.transition(candidate_weights_.data(), count, total, rng);
        chosen = candidate_dirs_[k];
        chosen_cell = candidate_cells_[k];
      }
      const std::uint32_t next = chosen_cell;
      here = step(here, chosen);
      route.cells.push_back(next);
      route.dirs.push_back(static_cast<std::uint8_t>(chosen));
      route.length += stepLength(chosen);
      route.cost += grid.moveCostInto(grid.index(here), chosen);
      if (setup.prices_turns)
        route.cost += previous_dir >= 0 ? setup.turn_price[turnSteps(previous_dir, chosen)] : setup.start_turn_price[chosen];
      visit(next);
      previous_dir = chosen;
      current = next;
      if (setup.waypoint_of_cell[next] == static_cast<std::int32_t>(target) && ++target == setup.waypoints.size() &&
          setup.prices_turns)
        route.cost += setup.leave_price.back()[chosen];  // the turn onto the goal heading
    }
    route.complete = true;
  }

  // Classic ACO's and EACI's walk (WaypointWalk).
  void walk(const WalkSetup& setup, SplitMix64& rng, AntRoute& route, StopPoll* stop = nullptr) {
    walk(setup, WaypointWalk{}, rng, route, stop);
  }

 private:
  // Visit marks are stamps, so a new walk costs no clearing.
  void beginWalk(std::size_t cell_count) {
    if (stamps_.size() != cell_count) {
      stamps_.assign(cell_count, 0);
      stamp_ = 0;
    }
    if (++stamp_ == 0) {
      std::fill(stamps_.begin(), stamps_.end(), 0);
      stamp_ = 1;
    }
  }
  bool visited(std::size_t cell) const { return stamps_[cell] == stamp_; }
  void visit(std::size_t cell) { stamps_[cell] = stamp_; }

  std::vector<std::uint32_t> stamps_;
  std::uint32_t stamp_ = 0;
  std::array<int, kDirections> candidate_dirs_{};
  std::array<std::uint32_t, kDirections> candidate_cells_{};
  std::array<double, kDirections> candidate_weights_{};
};

}  // namespace eaci
