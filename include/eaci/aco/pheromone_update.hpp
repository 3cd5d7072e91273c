// Pheromone updates after an iteration: classic ACO (Eq. 10-11), EACI's adaptive rule (Eq. 23-25)
// and MAACO's bounded one; and each as an update rule of a colony (aco/variants.hpp).
// A route's L_k is its cost (AntRoute::cost), which on a binary map is its length.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "eaci/aco/ant_route.hpp"
#include "eaci/aco/colony_parameters.hpp"
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

struct PheromoneBounds {
  double min = 0.0;
  double max = 0.0;
};

// MAACO's max-min bounds from the cheapest route so far, L_best (docs/algorithm.md, MAACO, choice 6):
// kWide: tau_max = 200 (1 / (2 (1 - rho)) + 1) / L_best, tau_min = tau_max / 500;
// kTight: tau_max = 1 / ((1 - rho) L_best), tau_min = tau_max / (2 max(W, H)).
inline PheromoneBounds maacoPheromoneBounds(MaacoBounds kind, double rho, double best_cost, int map_side) {
  PheromoneBounds b;
  if (kind == MaacoBounds::kWide) {
    b.max = 200.0 * (1.0 / (2.0 * (1.0 - rho)) + 1.0) / best_cost;
    b.min = b.max / 500.0;
  } else {
    b.max = 1.0 / ((1.0 - rho) * best_cost);
    b.min = b.max / (2.0 * map_side);
  }
  return b;
}

// Update rules: called after each iteration with the routes, the iteration's best and worst
// (indices, -1 when no ant arrived) and the cheapest cost found so far.
struct ClassicUpdate {  // Eq. 10-11
  double rho = 0.1;
  double q = 100.0;
  void operator()(PheromoneField& field, const std::vector<AntRoute>& routes, int, int, double) const {
    classicPheromoneUpdate(field, routes, rho, q);
  }
};

struct AdaptiveUpdate {  // Eq. 23-25
  double kappa = 0.9;
  double q = 100.0;
  double d_se = 1.0;
  void operator()(PheromoneField& field, const std::vector<AntRoute>& routes, int best, int worst, double) const {
    adaptivePheromoneUpdate(field, routes, best, worst, kappa, q, d_se);
  }
};

// MAACO: Eq. 10-11 with a fixed rho, then every edge within maacoPheromoneBounds of the
// cheapest route so far (none yet: no bounds).
struct BoundedUpdate {
  double rho = 0.2;
  double q = 2.5;
  MaacoBounds bounds = MaacoBounds::kWide;
  int map_side = 1;  // max(W, H)
  void operator()(PheromoneField& field, const std::vector<AntRoute>& routes, int, int, double best_cost) const {
    classicPheromoneUpdate(field, routes, rho, q);
    if (!std::isfinite(best_cost)) return;
    const PheromoneBounds b = maacoPheromoneBounds(bounds, rho, best_cost, map_side);
    field.clamp(b.min, b.max);
  }
};

}  // namespace eaci
