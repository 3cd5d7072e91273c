// Writers for `eaci_bench scale`: JSON (every run, example maps with routes), CSV (one row per
// map size x kind x planner), Markdown (time, memory, quality, early stopping).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "provenance.hpp"
#include "scale.hpp"

namespace eaci_bench {

// EACI with early stopping against the full run and A*, over the seeds both ran.
struct EarlyStopComparison {
  int seeds = 0;
  double full_ms = 0.0;
  double early_ms = 0.0;
  double astar_ms = 0.0;
  double time_saved_pct = 0.0;    // 1 - early / full (of the summed times)
  double length_cost_pct = 0.0;   // mean of early length / full length - 1
  double early_gap_pct = 0.0;     // mean gap of the early-stopped route to A*
  double early_iterations = 0.0;  // iterations run before stopping
  double first_iteration_ms = 0.0;  // set-up and the first iteration (mean over the early-stopped runs)
};

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EarlyStopComparison, seeds, full_ms, early_ms, astar_ms, time_saved_pct,
                                   length_cost_pct, early_gap_pct, early_iterations, first_iteration_ms)

EarlyStopComparison compareEarlyStop(const ScaleCase& c, VariantKey full_key, VariantKey early_key);

nlohmann::json scaleJson(const std::vector<ScaleCase>& cases, const ScaleOptions& options,
                         const Provenance& provenance);
std::string scaleCsv(const std::vector<ScaleCase>& cases);
std::string scaleMarkdown(const std::vector<ScaleCase>& cases, const ScaleOptions& options,
                          const Provenance& provenance);

}  // namespace eaci_bench
