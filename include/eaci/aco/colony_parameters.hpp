// The ant colony's settings (the paper's Section 5 defaults): how many ants, how long, the
// pheromone and heuristic weights, the islands, the region the ants walk on, the seed and the
// threads. They are a part of the planner's Parameters (planner/parameters.hpp), which names,
// reads and validates every one of them.
#pragma once

#include <cstdint>

namespace eaci {

enum class IslandStrategy {
  kGeodesic,  // on a shortest route, r_s apart, legs guided by exact grid distance (beyond the paper)
  kPaper,     // Eq. 13-15 on the auxiliary map, as the paper defines them
};

inline const char* toString(IslandStrategy s) {
  switch (s) {
    case IslandStrategy::kGeodesic: return "geodesic";
    case IslandStrategy::kPaper: return "paper";
  }
  return "?";
}

// MAACO's open choices (docs/algorithm.md, "MAACO"): the first of each is this project's decision.
enum class MaacoCandidates {
  kQuadrant,  // moves not against S -> E on either axis; else not against here -> E; else every move
  kNearest3,  // the three moves nearest in angle to the direction here -> E
};
enum class MaacoStartDistance {
  kWalked,    // d_sj: the route's length from S to j
  kStraight,  // d_sj: the straight line from S to j
};
enum class MaacoBounds {
  kWide,   // tau_max = 200 (1 / (2 (1 - rho)) + 1) / L_best, tau_min = tau_max / 500
  kTight,  // tau_max = 1 / ((1 - rho) L_best), tau_min = tau_max / (2 max(W, H))
};

inline const char* toString(MaacoCandidates c) { return c == MaacoCandidates::kQuadrant ? "quadrant" : "nearest3"; }
inline const char* toString(MaacoStartDistance d) { return d == MaacoStartDistance::kWalked ? "walked" : "straight"; }
inline const char* toString(MaacoBounds b) { return b == MaacoBounds::kWide ? "wide" : "tight"; }

struct ColonyParameters {
  int ants = 50;                 // m
  int max_iterations = 100;      // Nc_max
  double alpha = 1.1;            // pheromone weight (Eq. 8)
  double beta = 7.0;             // heuristic weight (Eq. 8)
  double q = 100.0;              // pheromone deposit constant Q (Eq. 11, 24)
  double kappa = 0.9;            // adaptive evaporation coefficient (Eq. 25)
  int islands = 9;               // N, islands including S and E (Eq. 13)
  double lambda = 3.0;           // pheromone expansion coefficient (Eq. 21)
  double epsilon = 0.5;          // angle coefficient of the turning cost (Eq. 17)
  // Classic ACO evaporation rate (Eq. 10) and uniform initial pheromone; the paper gives
  // neither. tau0 = 800 with Q = 100 is the common MATLAB ACO code's tau0 = 8 with Q = 1 and,
  // with rho = 0.1, puts the baseline's iterations and lost ants within a factor 2 of the
  // paper's ACO row on all four maps (docs/benchmarks.md, `eaci_bench sweep`).
  double aco_rho = 0.1;
  double aco_tau0 = 800.0;
  // MAACO (re-implemented from public descriptions, not the authors' code): the values both
  // public re-implementations use (alpha, Q, q0, a, wh_max, wh_min), and this project's
  // decisions where they differ (rho, C, k_h and the three choices; docs/algorithm.md).
  double maaco_alpha = 1.0;        // pheromone weight
  double maaco_q = 2.5;            // deposit constant Q
  double maaco_rho = 0.2;          // evaporation rate, fixed
  double maaco_tau0 = 1.0;         // C of the elliptical initial pheromone
  double maaco_q0 = 0.5;           // q0 of the pseudo-random transition before its schedule
  double maaco_turn_weight = 1.0;  // a, the weight of the turn term c_j
  double maaco_wh_max = 0.9;       // the bounds of the adaptive weight h
  double maaco_wh_min = 0.2;
  double maaco_k_h = 1.0;          // k of h = wh_max - (wh_max - wh_min) exp(-k d_jT / d_ST)
  MaacoCandidates maaco_candidates = MaacoCandidates::kQuadrant;
  MaacoStartDistance maaco_start_distance = MaacoStartDistance::kWalked;
  MaacoBounds maaco_bounds = MaacoBounds::kWide;
  IslandStrategy island_strategy = IslandStrategy::kGeodesic;
  double island_spacing_max = 2.0;   // geodesic islands: at most this many cells apart (0 = r_s only)
  // Geodesic islands: the ants walk on the cells at most this many moves from the cheapest
  // route (ColonyRegion), so memory and set-up follow the route, not the map; 0 = the whole
  // map. The paper's islands and classic ACO always use the whole map.
  int region_margin = 12;
  int early_stop_iterations = 0;  // stop after this many iterations without improvement; 0 = off
  // With early stopping on (early_stop_iterations > 0), geodesic EACI also stops as soon as its
  // best route costs at most (1 + stop_gap) x the cheapest route's cost, which its A* search
  // knows before the ants start: 0 = once a route is as cheap (no later iteration could beat
  // it); 0.01 = within 1 %. The paper's islands and classic ACO know no such cost.
  double stop_gap = 0.0;
  // The price of turning (issue #30), every planner's: a route's combined cost is its cost
  // (Parameters: the move costs) plus turn_cost x its heading change in radians, summed over
  // consecutive moves (a 45-degree corner adds turn_cost x pi/4; the first move turns
  // nothing). 0 = routes priced by their cost alone, as before, seed for seed. A* (--algorithm
  // astar) minimises the combined cost whenever turn_cost > 0 (search/heading_search.hpp); the
  // colonies score it as their L_k, in the walk's heuristic and in the pheromone update, and
  // geodesic islands sit on its cheapest route. docs/algorithm.md says why radians.
  double turn_cost = 0.0;
  std::uint64_t seed = 1;
  int threads = 1;  // ants of one iteration spread over this many threads; 0 = all cores
};

}  // namespace eaci
