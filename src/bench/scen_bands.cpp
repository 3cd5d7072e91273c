#include "scen_bands.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "statistics.hpp"

namespace eaci_bench {

double lengthBandLower(double optimal_length) {
  return std::exp2(std::floor(std::log2(std::max(optimal_length, 1.0))));
}

std::vector<ScenLengthBand> lengthBands(const std::vector<ScenProblemResult>& problems) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  std::map<double, std::vector<const ScenProblemResult*>> grouped;
  for (const ScenProblemResult& r : problems) grouped[lengthBandLower(r.problem.optimal_length)].push_back(&r);
  std::vector<ScenLengthBand> bands;
  for (const auto& [lower, members] : grouped) {
    ScenLengthBand band;
    band.lower = lower;
    band.upper = 2.0 * lower;
    band.problems = static_cast<int>(members.size());
    std::vector<double> ratios, gaps, astar_ms, eaci_ms;
    band.worst_gap_pct = -kInfinity;
    for (const ScenProblemResult* r : members) {
      if (std::isfinite(r->time_ratio)) ratios.push_back(r->time_ratio);
      if (r->eaci_successes > 0) {
        gaps.push_back(r->eaci_gap_pct);
        band.worst_gap_pct = std::max(band.worst_gap_pct, r->eaci_worst_gap_pct);
      }
      astar_ms.push_back(r->astar.time_ms);
      eaci_ms.push_back(r->eaci_time_ms);
      band.eaci_runs += static_cast<int>(r->eaci.size());
      band.eaci_failures += static_cast<int>(r->eaci.size()) - r->eaci_successes;
    }
    if (band.worst_gap_pct == -kInfinity) band.worst_gap_pct = kInfinity;
    band.median_time_ratio = ratios.empty() ? kInfinity : median(ratios);
    band.max_time_ratio = ratios.empty() ? kInfinity : *std::max_element(ratios.begin(), ratios.end());
    band.median_gap_pct = gaps.empty() ? kInfinity : median(gaps);
    band.median_astar_ms = median(astar_ms);
    band.median_eaci_ms = median(eaci_ms);
    bands.push_back(band);
  }
  return bands;
}

}  // namespace eaci_bench
