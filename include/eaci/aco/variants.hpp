// The ant colonies as compositions of rules: the walk (candidate moves, heuristic, transition,
// whether a leg's goal is taken at once), the pheromone update with its evaporation and bounds,
// and how routes of equal cost rank. The colony (colony.hpp) and the walk (ant_walk.hpp) are
// shared: the per-ant random streams, the thread-count independence and the lost-ant count (an
// ant left without a candidate move) are theirs. The initial pheromone is each solver's
// (solvers.hpp). Adding a variant is writing a struct like these.
#pragma once

#include <algorithm>

#include "eaci/aco/ant_walk.hpp"
#include "eaci/aco/candidate_moves.hpp"
#include "eaci/aco/colony_parameters.hpp"
#include "eaci/aco/maaco_heuristic.hpp"
#include "eaci/aco/pheromone_update.hpp"
#include "eaci/aco/transition.hpp"

namespace eaci {

// Classic ACO (Section 3, Eq. 8-11): heuristic 1 / d_jg, roulette, fixed evaporation aco_rho.
struct ClassicAcoRules : WaypointWalk {
  ClassicUpdate update;
  static constexpr bool kFewerTurnsOnTies = false;  // equal costs: the lowest ant index

  explicit ClassicAcoRules(const ColonyParameters& p) : update{p.aco_rho, p.q} {}
};

// EACI (Section 4): the walk through the islands with the turning-aware heuristic (Eq. 16-17,
// set up in WalkSetup), roulette, the adaptive update (Eq. 23-25).
struct EaciRules : WaypointWalk {
  AdaptiveUpdate update;
  static constexpr bool kFewerTurnsOnTies = false;

  EaciRules(const ColonyParameters& p, double d_se) : update{p.kappa, p.q, d_se} {}
};

// MAACO (re-implemented from public descriptions, not the authors' code; docs/algorithm.md):
// the goal-direction filter, eta = 1 / (g d_sj + h d_jT + a c_j), the pseudo-random transition
// with its q0 schedule, the leg's goal not taken at once (eta is finite there), fixed
// evaporation maaco_rho with max-min bounds, and fewer turns first among equally short routes.
struct MaacoRules {
  GoalDirectionMoves candidates;
  MaacoHeuristic heuristic;
  PseudoRandomTransition transition;
  BoundedUpdate update;
  static constexpr bool kTakeGoalWhenNeighbour = false;
  static constexpr bool kFewerTurnsOnTies = true;

  MaacoRules(const ColonyParameters& p, Cell start, Cell goal, int map_side)
      : candidates(p.maaco_candidates == MaacoCandidates::kNearest3, start, goal),
        heuristic(MaacoHeuristicWeights{p.maaco_wh_max, p.maaco_wh_min, p.maaco_k_h, p.maaco_turn_weight},
                  p.maaco_start_distance == MaacoStartDistance::kStraight, start, goal),
        transition{p.maaco_q0, p.maaco_q0},
        update{p.maaco_rho, p.maaco_q, p.maaco_bounds, map_side} {}
};

}  // namespace eaci
