// One ant's walk from S to E through the waypoints (Eq. 8 with Eq. 9 or Eq. 16-17),
// shared by classic ACO (waypoints S, E) and EACI (waypoints = islands).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "eaci/aco/ant_route.hpp"
#include "eaci/aco/heuristic.hpp"
#include "eaci/aco/leg_distance_field.hpp"
#include "eaci/aco/pheromone_field.hpp"
#include "eaci/aco/random.hpp"
#include "eaci/grid/binary_grid.hpp"

namespace eaci {

enum class HeuristicRule {
  kGoalDistance,  // Eq. 9, classic ACO
  kTurningAware,  // Eq. 16-17, EACI
};

// Everything an ant reads; shared by all ants of an iteration and never written during it.
struct WalkSetup {
  const BinaryGrid* grid = nullptr;
  const PheromoneField* pheromone = nullptr;
  std::vector<Cell> waypoints;                // L_1 = S, ..., L_N = E
  std::vector<std::int32_t> waypoint_of_cell;  // per grid cell: its index in `waypoints`, or -1
  // d_jg of the heuristic: empty -> Euclidean distance to the leg's goal (the paper);
  // else leg_distance[z] is the grid distance to waypoint z (geodesic islands).
  std::vector<LegDistanceField> leg_distance;
  HeuristicRule heuristic = HeuristicRule::kGoalDistance;
  double beta = 7.0;
  double epsilon = 0.5;

  WalkSetup(const BinaryGrid& g, const PheromoneField& field, std::vector<Cell> points, HeuristicRule rule,
            double beta_, double epsilon_)
      : grid(&g), pheromone(&field), waypoints(std::move(points)), waypoint_of_cell(g.cellCount(), -1),
        heuristic(rule), beta(beta_), epsilon(epsilon_) {
    for (std::size_t w = 0; w < waypoints.size(); ++w)
      waypoint_of_cell[g.index(waypoints[w])] = static_cast<std::int32_t>(w);
  }
};

// Walks ants one after the other, reusing its memory: nothing is allocated during a walk
// once the route's vectors have grown to the longest route seen.
class AntWalker {
 public:
  // The ant's taboo list spans the whole route (spec 3.5): it never enters a cell twice.
  // It may not step on an island other than the one it is heading for, so the route visits
  // the islands in order. When its current goal is an allowed neighbour it takes it at once
  // (the d = 0 guard of Eq. 9). An ant with no allowed move is lost: route.complete = false.
  void walk(const WalkSetup& setup, SplitMix64& rng, AntRoute& route) {
    const BinaryGrid& grid = *setup.grid;
    beginWalk(grid.cellCount());
    std::uint32_t current = static_cast<std::uint32_t>(grid.index(setup.waypoints.front()));
    route.reset(current);
    visit(current);
    std::size_t target = 1;
    int previous_dir = -1;
    while (target < setup.waypoints.size()) {
      const Cell here = grid.cellAt(current);
      const Cell goal = setup.waypoints[target];
      int count = 0;
      int chosen = -1;
      double total = 0.0;
      for (int d = 0; d < kDirections; ++d) {
        if (!grid.canMove(here, d)) continue;
        const Cell next = step(here, d);
        const std::size_t j = grid.index(next);
        if (visited(j)) continue;
        const std::int32_t waypoint = setup.waypoint_of_cell[j];
        if (waypoint == static_cast<std::int32_t>(target)) {
          chosen = d;  // the goal of this leg is a neighbour: take it
          break;
        }
        if (waypoint >= 0) continue;  // another island: not on this leg
        const double distance = setup.leg_distance.empty() ? std::hypot(next.row - goal.row, next.col - goal.col)
                                                           : setup.leg_distance[target].at(next);
        const double eta = setup.heuristic == HeuristicRule::kGoalDistance
                               ? goalDistanceHeuristic(distance)
                               : turningAwareHeuristic(distance, turningCost(previous_dir, d, setup.epsilon));
        const double weight = setup.pheromone->weight(current, d) * std::pow(eta, setup.beta);  // Eq. 8 numerator
        candidate_dirs_[count] = d;
        candidate_weights_[count] = weight;
        total += weight;
        ++count;
      }
      if (chosen < 0) {
        if (count == 0) return;  // deadlock: a lost ant
        chosen = rouletteChoice(count, total, rng);
      }
      const std::uint32_t next = static_cast<std::uint32_t>(grid.index(step(here, chosen)));
      route.cells.push_back(next);
      route.dirs.push_back(static_cast<std::uint8_t>(chosen));
      route.length += stepLength(chosen);
      visit(next);
      previous_dir = chosen;
      current = next;
      if (setup.waypoint_of_cell[next] == static_cast<std::int32_t>(target)) ++target;
    }
    route.complete = true;
  }

 private:
  // Eq. 8 by roulette wheel. Degenerate weights (all zero or overflowing) fall back to a uniform choice.
  int rouletteChoice(int count, double total, SplitMix64& rng) const {
    if (!(total > 0.0) || !std::isfinite(total)) {
      return candidate_dirs_[static_cast<std::size_t>(rng.uniform() * count)];
    }
    const double ball = rng.uniform() * total;
    double cumulative = 0.0;
    for (int k = 0; k < count; ++k) {
      cumulative += candidate_weights_[k];
      if (ball < cumulative) return candidate_dirs_[k];
    }
    return candidate_dirs_[count - 1];
  }

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
  std::array<double, kDirections> candidate_weights_{};
};

}  // namespace eaci
