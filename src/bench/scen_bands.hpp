// Route length as its own axis of `eaci_bench scen`: the problems grouped into bands of the
// optimal length by powers of two, [2^k, 2^(k+1)) cells (lengths below 1 in the first band),
// with per band the median EACI/A* time ratio, the median and worst gap, and the median
// absolute times. Peak memory is not per band: scen plans in its own process, one problem after
// the other, so the process's peak RSS is the largest problem's (docs/benchmarks.md section 10
// measures memory per route in separate processes).
#pragma once

#include <vector>

#include "scen.hpp"

namespace eaci_bench {

struct ScenLengthBand {
  double lower = 0.0;  // optimal length in [lower, upper)
  double upper = 0.0;
  int problems = 0;
  int eaci_runs = 0;
  int eaci_failures = 0;
  double median_time_ratio = 0.0;  // over the problems' ratios (EACI median over seeds / A*)
  double max_time_ratio = 0.0;
  double median_gap_pct = 0.0;     // over the problems' mean gaps (problems EACI solved)
  double worst_gap_pct = 0.0;      // over every successful EACI run
  double median_astar_ms = 0.0;
  double median_eaci_ms = 0.0;
};

// The band k = floor(log2(max(optimal, 1))) of one optimal length, as its lower bound 2^k.
double lengthBandLower(double optimal_length);

// Bands holding at least one problem, shortest first.
std::vector<ScenLengthBand> lengthBands(const std::vector<ScenProblemResult>& problems);

}  // namespace eaci_bench
