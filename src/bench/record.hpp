// The one record every eaci_bench command writes: a timed plan (RunRecord: the PlanResult's
// numbers, wall times and curves) with its context (command, map, variant, seed, problem, the
// parameters that differ from the defaults, what the command measured besides, where it ran),
// appended as one JSON line to OUT/<command>.jsonl. scripts/bench_report.py makes every table
// and figure of docs/benchmarks.md from these lines.
#pragma once

#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/cell_json.hpp"
#include "eaci/aco/parameters.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/planner.hpp"

namespace eaci_bench {

struct RunRecord {
  std::uint64_t seed = 0;
  bool success = false;            // a route the colony found (geodesic EACI's fallback to its search route is none)
  double length = std::numeric_limits<double>::infinity();           // cells
  double cost = std::numeric_limits<double>::infinity();             // PlanResult::cost (the length on a binary map)
  double smoothed_length = std::numeric_limits<double>::infinity();  // cells, along smoothed_path
  double total_turn_deg = 0.0;
  int iterations_to_converge = 0;  // iteration that first reached the final route (0 for A*)
  int iterations_run = 0;
  long long lost_ants_total = 0;
  bool stopped_early = false;
  bool interrupted = false;        // a time budget stopped it
  bool route_from_search = false;
  double time_ms = 0.0;            // wall time around eaci::plan()
  double cpu_ms = 0.0;             // CPU time of the process around eaci::plan()
  double time_to_best_ms = 0.0;    // wall time until the iteration that found the final route ended
  double first_iteration_ms = 0.0; // wall time until the first iteration ended (set-up included)
  // Per iteration (B2's renames of PlanResult's curves touch only recordFrom in record.cpp).
  std::vector<double> best_cost_so_far;
  std::vector<double> iteration_best_cost;
  std::vector<int> lost_ants_per_iteration;
  std::vector<double> iteration_end_ms;
  eaci::CellPath path;
  eaci::CellPath smoothed_path;
  std::vector<eaci::Cell> islands;
};

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(RunRecord, seed, success, length, cost, smoothed_length, total_turn_deg,
                                                iterations_to_converge, iterations_run, lost_ants_total, stopped_early,
                                                interrupted, route_from_search, time_ms, cpu_ms, time_to_best_ms,
                                                first_iteration_ms, best_cost_so_far, iteration_best_cost,
                                                lost_ants_per_iteration, iteration_end_ms, path, smoothed_path, islands)

// The curves and cells only when asked (they dominate the size); the smoothed route only when it differs.
nlohmann::json toJson(const RunRecord& run, bool with_curves, bool with_path);
RunRecord runRecordFromJson(nlohmann::json j);  // null as +infinity; left-out fields keep their defaults

struct PlanRequest {
  eaci::GridView view;
  eaci::Cell start;
  eaci::Cell goal;
  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;
  eaci::Parameters params;
  double budget_ms = 0.0;  // > 0: stop between iterations once this much wall time has passed
  eaci::PlannerWorkspace* workspace = nullptr;  // kept between plans (as the ROS node keeps one); null: the plan's own
};

// Wall time around plan() alone; an observer notes the end of each iteration (it only reads the clock).
RunRecord timedPlan(const PlanRequest& request);
// The same run, timed `repeats` times (microsecond plans): the first run's record with the median times.
RunRecord timedPlanMedian(const PlanRequest& request, int repeats);
// One untimed run: the strongest edge leaving each cell at the listed iterations (0 = initial),
// as [{"iteration": k, "strongest": [...]}, ...].
nlohmann::json pheromoneSnapshots(const PlanRequest& request, const std::vector<int>& iterations);

// Source commit, compiler, machine, load and command line of one command's run.
nlohmann::json provenance(const std::string& command_line);

// One line of OUT/<command>.jsonl.
struct Record {
  std::string map;
  std::string variant;
  nlohmann::json problem = nlohmann::json::object();  // start, goal and what else defines the problem
  eaci::Parameters params;
  RunRecord run;
  nlohmann::json extra = nlohmann::json::object();    // the command's own measures (memory, route checks, ...)
  bool with_curves = false;
  bool with_path = false;
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
