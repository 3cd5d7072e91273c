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
  std::uint64_t seed = 1;
  int threads = 1;  // ants of one iteration spread over this many threads; 0 = all cores
};

}  // namespace eaci
