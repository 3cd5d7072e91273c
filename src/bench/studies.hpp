// The studies of eaci_bench (what each runs: docs/benchmarks.md; the records: record.hpp). Each
// appends one record per plan to OUT/<command>.jsonl. Timing-only measurements belong in
// microbench/ (Google Benchmark), not here.
#pragma once

#include <string>
#include <vector>

#include "eaci/planner/parameters.hpp"
#include "eaci/grid/inflation.hpp"
#include "map_generator.hpp"

namespace eaci_bench {

struct PaperOptions {
  std::string maps_dir;
  int runs = 20;
  int threads = 1;
  std::vector<int> snapshot_iterations = {0, 1, 5, 15, 30};  // paper: pheromone snapshots of EACI's seed 1
};

struct FrontOptions {  // front: length against total corner angle on the paper's maps (issue #30)
  std::string maps_dir;
  int runs = 20;      // EACI seeds 1..runs per map and island strategy
  int threads = 1;
  std::vector<double> turn_costs = {0, 0.05, 0.1, 0.2, 0.35, 0.5, 0.75, 1, 1.5, 2, 3, 5, 10};  // per radian
  std::vector<double> eaci_turn_costs = {0, 0.2, 0.5, 1};  // EACI's runs, per radian
};

struct GeneratedOptions {  // scale and deadline
  std::vector<int> sizes = {50, 100, 200, 400, 800};
  std::vector<MapKind> kinds = {MapKind::kRooms, MapKind::kClutter};
  int runs = 0;                 // scale: seeds per case, 0 = 5 up to 400 cells, else 3; deadline: map seeds
  double budget_s = 60.0;       // a colony run stops between iterations after this long
  double slow_run_s = 10.0;     // a planner whose run takes longer runs for the first seed only
  int early_stop_iterations = 10;
  int example_max_size = 200;   // keep maps and routes of seed 1 up to this size (figures)
  std::vector<double> limits_s = {0.1, 0.25, 0.5, 1.0, 2.0};  // deadline
  int threads = 1;              // deadline
};

struct CostsOptions {
  std::vector<int> sizes = {100, 200, 400, 800};
  std::vector<MapKind> kinds = {MapKind::kRooms, MapKind::kClutter};
  int runs = 0;               // map seeds per generated case; 0 = 20 up to 400 cells, else 10
  std::string lab_map = "maps/lab.yaml";  // empty: no lab runs
  int lab_seeds = 10;         // EACI seeds per lab start/goal pair
  double budget_s = 60.0;
  bool quick = false;         // sizes 100 and 200, 2 seeds, 2 lab seeds
  // The lab: config/costmap_common_params.yaml (inflation_radius 0.30, cost_scaling_factor 8.0)
  // and the inscribed radius costmap_2d derives from its padded footprint (0.1025 + 0.01 m).
  eaci::InflationParameters lab_inflation{0.30, 0.1125, 8.0};
  // Generated maps, in cells: the lab's 6-cell band and its decay per cell, an inscribed radius
  // of 1 cell so that 3-cell doors stay open.
  eaci::InflationParameters generated_inflation{6.0, 1.0, 0.4};
  GeneratorOptions generator{3, 5};  // doors of 3-5 cells (2-cell doors would close)
  int example_max_size = 200;
};

struct ScenOptions {
  std::string scen_path;
  int every = 1;              // problems 0, K, 2K, ... of the file
  std::string map_dir;        // empty: the .scen file's directory
  int seeds = 1;
  double budget_s = 60.0;
  eaci::Parameters parameters;  // the defaults or --params; corner cutting always forbidden
};

class RecordWriter;

void runPaper(const PaperOptions& options, RecordWriter& out);
void runSweep(const PaperOptions& options, RecordWriter& out);
void runFront(const FrontOptions& options, RecordWriter& out);
void runScale(const GeneratedOptions& options, RecordWriter& out);
void runDeadline(const GeneratedOptions& options, RecordWriter& out);
void runCosts(CostsOptions options, RecordWriter& out);
// Returns the number of problems whose A* length differs from the file's optimal length.
int runScen(const ScenOptions& options, RecordWriter& out);

}  // namespace eaci_bench
