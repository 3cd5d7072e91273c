// costmap_2d's inflation on the core's grids: obstacles spread a cost that decays with the
// distance from them, so that routes keep off walls.
//
// The costs are costmap_2d's (inflation_layer.h, computeCost): distance 0 -> 254 (lethal), at most
// the inscribed radius -> 253 (inscribed), at most the inflation radius ->
// (unsigned char)((253 - 1) * exp(-cost_scaling_factor * (distance - inscribed_radius))), beyond
// -> 0. Distances are exact Euclidean distances between cell centres (distance_transform.hpp);
// costmap_2d also measures between cell centres but stops at ceil(inflation_radius / resolution)
// cells, here a cell is inflated when its distance in metres is at most the inflation radius.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/costmap_costs.hpp"
#include "eaci/number_text.hpp"
#include "eaci/grid/distance_transform.hpp"
#include "eaci/grid/grid_view.hpp"

namespace eaci {

// costmap_2d's inflation parameters, in metres (cost_scaling_factor in 1/m).
struct InflationParameters {
  double inflation_radius = 0.0;
  double inscribed_radius = 0.0;
  double cost_scaling_factor = 10.0;
};

// Why the parameters cannot be used (empty if they can): radii finite and >= 0, the inscribed
// radius at most the inflation radius, cost_scaling_factor finite and >= 0.
inline std::string inflationError(const InflationParameters& p) {
  if (!std::isfinite(p.inflation_radius) || p.inflation_radius < 0)
    return "inflation_radius must be a distance >= 0 m, not " + formatNumber(p.inflation_radius);
  if (!std::isfinite(p.inscribed_radius) || p.inscribed_radius < 0)
    return "inscribed_radius must be a distance >= 0 m, not " + formatNumber(p.inscribed_radius);
  if (p.inscribed_radius > p.inflation_radius)
    return "inscribed_radius " + formatNumber(p.inscribed_radius) + " m exceeds inflation_radius " +
           formatNumber(p.inflation_radius) + " m";
  if (!std::isfinite(p.cost_scaling_factor) || p.cost_scaling_factor < 0)
    return "cost_scaling_factor must be a number >= 0, not " + formatNumber(p.cost_scaling_factor);
  return "";
}

// Distances within this of a radius count as on it (3 cells x 0.1 m is 0.30000000000000004 m).
constexpr double kInflationDistanceSlack = 1e-9;  // m

// The inflation cost of a cell `distance` metres from the nearest obstacle (costmap_2d's computeCost).
inline std::uint8_t inflationCost(double distance, const InflationParameters& p) {
  if (distance == 0.0) return kCostmapLethal;
  if (distance <= p.inscribed_radius + kInflationDistanceSlack) return kCostmapInscribed;
  if (!(distance <= p.inflation_radius + kInflationDistanceSlack)) return kCostmapFree;
  const double factor = std::exp(-p.cost_scaling_factor * (distance - p.inscribed_radius));
  return static_cast<std::uint8_t>((kCostmapInscribed - 1) * factor);
}

// How the planners read inflatedCosts(): 253 and 254 are obstacles, 255 unknown, the rest costs.
inline CellInterpretation inflatedCostsInterpretation(bool allow_unknown) {
  return CellInterpretation::costmap(kCostmapInscribed, allow_unknown);
}

// The view's map inflated, as a costmap_2d char map (row-major, row 0 = top): known obstacles
// 254, unknown cells 255 (kept; unknown cells are not inflated from), every other cell the
// larger of its own cost and its inflation cost. `resolution` is metres per cell (> 0); the
// parameters must pass inflationError(). Read it with inflatedCostsInterpretation().
inline std::vector<std::uint8_t> inflatedCosts(const GridView& view, double resolution, const InflationParameters& p) {
  const std::vector<double> distance = obstacleDistances(view);
  std::vector<std::uint8_t> costs(view.cellCount(), kCostmapFree);
  const CellInterpretation& interpretation = view.interpretation();
  for (int r = 0; r < view.height(); ++r) {
    for (int c = 0; c < view.width(); ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * static_cast<std::size_t>(view.width()) + static_cast<std::size_t>(c);
      const std::uint8_t value = view.value(Cell{r, c});
      if (value == interpretation.unknown_value) costs[i] = kCostmapUnknown;
      else if (value >= interpretation.lethal_cost) costs[i] = kCostmapLethal;
      else costs[i] = std::max(interpretation.cost(value), inflationCost(distance[i] * resolution, p));
    }
  }
  return costs;
}

}  // namespace eaci
