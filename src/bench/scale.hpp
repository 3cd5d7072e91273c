// `eaci_bench scale`: generated rooms and clutter maps of growing size, the robot's move
// rule (no corner cutting), default parameters (geodesic EACI). EACI, classic ACO and A*
// per map, each plan in its own child process: time on one thread and on all cores, peak
// memory, gap to A*, lost ants, success, iterations; EACI with early stopping beside A*.
#pragma once

#include <string>
#include <vector>

#include "eaci/planner.hpp"
#include "map_generator.hpp"
#include "run_record.hpp"
#include "statistics.hpp"
#include "variant_key.hpp"

namespace eaci_bench {

struct ScaleOptions {
  std::vector<int> sizes = {50, 100, 200, 400, 800};
  std::vector<MapKind> kinds = {MapKind::kRooms, MapKind::kClutter};
  int runs = 0;                 // seeds per case; 0 = by size (see seedsFor)
  double budget_s = 60.0;       // a colony run stops between iterations after this long
  double slow_run_s = 10.0;     // a variant whose run takes longer runs for the first seed only
  int early_stop_iterations = 10;
  int example_max_size = 200;   // store maps and routes of seed 1 up to this size (for plots)
  std::string out_dir = "out/bench";
  std::string command_line;
};

struct ScaleVariant {
  VariantKey key = VariantKey::kEaci1t;
  std::string label;
  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;
  int threads = 1;              // 0 = all cores
  int early_stop_iterations = 0;
};

std::vector<ScaleVariant> scaleVariants(int early_stop_iterations);
int seedsFor(int size, int requested);

struct ScaleRun {
  RunRecord record;
  double optimum = 0.0;
  double gap_pct = 0.0;          // length over the A* optimum; +inf on failure
  double peak_rss_mb = 0.0;      // the child's peak resident set
  double plan_rss_mb = 0.0;      // peak minus the child's resident set before the plan
};

struct ScaleVariantResult {
  ScaleVariant variant;
  std::vector<ScaleRun> runs;
  Summary summary;               // lengths, iterations, lost ants, times
  double avg_gap_pct = 0.0;      // over successful runs
  double max_gap_pct = 0.0;
  double max_peak_rss_mb = 0.0;
  double max_plan_rss_mb = 0.0;
  int skipped_seeds = 0;
};

struct ScaleCase {
  int size = 0;
  MapKind kind = MapKind::kRooms;
  std::vector<GeneratedMap> maps;  // one per seed (cells dropped after the runs except examples)
  std::vector<ScaleVariantResult> variants;
  std::vector<std::string> notes;
};

int runScaleCommand(const ScaleOptions& options);

}  // namespace eaci_bench
