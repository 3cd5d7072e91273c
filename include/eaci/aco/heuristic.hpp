// The turning cost of Eq. 17. The heuristic information eta_ij of Eq. 9 (classic ACO) and
// Eq. 16 (EACI) is computed by the ant walk (WalkSetup::heuristicWeight in ant_walk.hpp).
#pragma once

#include <cmath>

#include "eaci/grid/moves.hpp"

namespace eaci {

// Eq. 17: sigma_ij = k * epsilon for a turn of k * 45 degrees between the previous move
// and the candidate move; no previous move (first step of a route): sigma = 0.
inline double turningCost(int previous_dir, int candidate_dir, double epsilon) {
  if (previous_dir < 0) return 0.0;
  return turnSteps(previous_dir, candidate_dir) * epsilon;
}

}  // namespace eaci
