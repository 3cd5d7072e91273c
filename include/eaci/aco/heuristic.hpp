// Heuristic information eta_ij of Eq. 9 (classic ACO) and Eq. 16-17 (EACI).
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

// Eq. 9: eta_ij = 1 / d_jg, d_jg = Euclidean distance from j to the goal.
inline double goalDistanceHeuristic(double distance_to_goal) { return 1.0 / distance_to_goal; }

// Eq. 16: eta_ij = 1 / (d_jg + sigma_ij), d_jg = distance from j to the current leg's goal.
inline double turningAwareHeuristic(double distance_to_goal, double turning_cost) {
  return 1.0 / (distance_to_goal + turning_cost);
}

}  // namespace eaci
