// The planners the benchmarks run, each with its one key: the "key" of the JSON, the algorithm
// column of the CSV, and what scripts/plot_benchmarks.py looks them up by.
#pragma once

#include <string>

#include "eaci/planner/parameters.hpp"

namespace eaci_bench {

enum class VariantKey {
  kAStar,          // exact A*
  kAco,            // `paper`: classic ACO with our defaults
  kAcoStrong,      // `paper`: classic ACO with strong deposits
  kEaciPaper,      // `paper`, `sweep`: EACI with the paper's islands
  kEaciGeodesic,   // `paper`, `sweep`: EACI with geodesic islands
  kEaci1t,         // `scale`: EACI, one thread
  kEaciAll,        // `scale`: EACI, all cores
  kEaciEarly1t,    // `scale`: EACI with early stopping, one thread
  kEaciEarlyAll,   // `scale`: EACI with early stopping, all cores
  kAco1t,          // `scale`: classic ACO, one thread
  kAcoAll,         // `scale`: classic ACO, all cores
  kAStarSmoothed,  // `costs`: A* with smooth_path
  kEaciSmoothed1t, // `costs`: EACI with smooth_path, one thread
};

inline const char* toString(VariantKey key) {
  switch (key) {
    case VariantKey::kAStar: return "astar";
    case VariantKey::kAco: return "aco";
    case VariantKey::kAcoStrong: return "aco-strong";
    case VariantKey::kEaciPaper: return "eaci-paper";
    case VariantKey::kEaciGeodesic: return "eaci-geodesic";
    case VariantKey::kEaci1t: return "eaci-1t";
    case VariantKey::kEaciAll: return "eaci-all";
    case VariantKey::kEaciEarly1t: return "eaci-early-1t";
    case VariantKey::kEaciEarlyAll: return "eaci-early-all";
    case VariantKey::kAco1t: return "aco-1t";
    case VariantKey::kAcoAll: return "aco-all";
    case VariantKey::kAStarSmoothed: return "astar-smoothed";
    case VariantKey::kEaciSmoothed1t: return "eaci-smoothed-1t";
  }
  return "?";
}

// EACI with `island_strategy` islands ("paper", "geodesic"; throws eaci::ParameterError for others).
inline VariantKey eaciVariantKey(const std::string& island_strategy) {
  eaci::Parameters p;
  eaci::setParameter(p, "island_strategy", island_strategy);
  switch (p.island_strategy) {
    case eaci::IslandStrategy::kPaper: return VariantKey::kEaciPaper;
    case eaci::IslandStrategy::kGeodesic: return VariantKey::kEaciGeodesic;
  }
  return VariantKey::kEaciGeodesic;
}

}  // namespace eaci_bench
