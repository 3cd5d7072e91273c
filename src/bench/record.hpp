// The one record every eaci_bench command writes, one JSON line per plan in OUT/<command>.jsonl:
//   command, map, variant, seed;
//   problem    - start, goal and what else defines the problem (map size and seed, optimum, ...);
//   parameters - the planner parameters that differ from the defaults (the seed is the record's);
//   run        - the plan: PlanResult's numbers (success, length, cost, turning, iterations, lost
//                ants, ...), wall and CPU times, optionally the per-iteration curves and the cells;
//   extra      - what the study measured besides (peak memory, the driven route's checks, ...);
//   provenance - source commit, compiler, machine, load and command line.
// scripts/bench_report.py makes every table and figure of docs/benchmarks.md from these lines.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/cell_json.hpp"
#include "eaci/planner/parameters.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/planner.hpp"

namespace eaci_bench {

struct TimedPlanRequest {
  eaci::GridView view;
  eaci::Cell start;
  eaci::Cell goal;
  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;
  eaci::Parameters params;
  double budget_ms = 0.0;  // > 0: stop between iterations once this much wall time has passed
  eaci::PlannerWorkspace* workspace = nullptr;  // kept between plans (as the ROS node keeps one); null: the plan's own
};

// One eaci::plan(), timed (an observer notes the end of each iteration; it only reads the clock),
// as the record's "run". `with_curves`: the per-iteration curves; `with_path`: the route's cells,
// the smoothed route's when it differs, the islands. A non-finite number is written as null.
nlohmann::json timedPlan(const TimedPlanRequest& request, bool with_curves, bool with_path);
// Microsecond plans: the first run with the median wall and CPU time of `repeats` runs.
nlohmann::json timedPlanMedian(const TimedPlanRequest& request, int repeats, bool with_path);
// One untimed run: the strongest pheromone leaving each cell at the listed iterations (0 = initial).
nlohmann::json pheromoneSnapshots(const TimedPlanRequest& request, const std::vector<int>& iterations);
// The route a run's JSON holds: the smoothed one when `smoothed` and it was written, else the grid route.
eaci::CellPath routeOf(const nlohmann::json& run, bool smoothed);

struct Record {
  std::string map;
  std::string variant;
  nlohmann::json problem = nlohmann::json::object();
  eaci::Parameters params;
  nlohmann::json run;
  nlohmann::json extra = nlohmann::json::object();
};

class RecordWriter {
 public:
  // Starts OUT/<command>.jsonl afresh.
  RecordWriter(const std::string& out_dir, const std::string& command, const std::string& command_line);
  void append(const Record& record);
  const std::string& path() const { return path_; }

 private:
  std::string command_;
  std::string path_;
  nlohmann::json provenance_;
  nlohmann::json defaults_;
  std::ofstream out_;
};

}  // namespace eaci_bench
