// Pheromone updates after an iteration: classic ACO (Eq. 10-11) and EACI's adaptive rule (Eq. 23-25).
// A route's L_k is its cost (AntRoute::cost), which on a binary map is its length.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "eaci/aco/ant_route.hpp"
#include "eaci/aco/pheromone_field.hpp"

namespace eaci {

inline void depositOnRoute(PheromoneField& field, const AntRoute& route, double amount) {
  for (std::size_t k = 0; k < route.dirs.size(); ++k) field.deposit(route.cells[k], route.dirs[k], amount);
}

// Eq. 10-11: tau <- (1 - rho) tau + sum_k Q / L_k over the edges of every complete route.
inline void classicPheromoneUpdate(PheromoneField& field, const std::vector<AntRoute>& routes, double rho, double q) {
  field.evaporate(rho);
  for (const AntRoute& route : routes)
    if (route.complete) depositOnRoute(field, route, q / route.cost);
  field.refreshChanged();
}

// Eq. 25: rho = kappa * d_SE / L_best, capped at 1 so that (1 - rho) never turns negative.
inline double adaptiveEvaporationRate(double kappa, double d_se, double best_cost) {
  return std::min(1.0, kappa * d_se / best_cost);
}

// Eq. 24: reward on the iteration's best route, penalty on its worst.
inline double bestRouteReward(double kappa, double q, double d_se, double best_cost) {
  return kappa * q * d_se / (best_cost * best_cost);
}
inline double worstRoutePenalty(double kappa, double q, double d_se, double best_cost, double worst_cost) {
  return -kappa * q * d_se / (worst_cost * best_cost);
}

// Eq. 23: tau <- (1 - rho) tau + sum_k Q / L_k + rho * dtau*, with L_best / L_worst the
// cheapest / costliest complete routes of this iteration (`best`, `worst` index `routes`).
// An iteration without a complete route leaves the field as it is.
inline void adaptivePheromoneUpdate(PheromoneField& field, const std::vector<AntRoute>& routes, int best, int worst,
                                    double kappa, double q, double d_se) {
  if (best < 0) return;
  const double best_cost = routes[static_cast<std::size_t>(best)].cost;
  const double worst_cost = routes[static_cast<std::size_t>(worst)].cost;
  const double rho = adaptiveEvaporationRate(kappa, d_se, best_cost);
  field.evaporate(rho);
  for (const AntRoute& route : routes)
    if (route.complete) depositOnRoute(field, route, q / route.cost);
  depositOnRoute(field, routes[static_cast<std::size_t>(best)], rho * bestRouteReward(kappa, q, d_se, best_cost));
  depositOnRoute(field, routes[static_cast<std::size_t>(worst)],
                 rho * worstRoutePenalty(kappa, q, d_se, best_cost, worst_cost));
  field.refreshChanged();
}

}  // namespace eaci
