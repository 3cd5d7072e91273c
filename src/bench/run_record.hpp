// One timed plan as the benchmarks record it: the PlanResult's numbers, wall times and curves.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/cell_json.hpp"
#include "eaci/grid/cell.hpp"

namespace eaci_bench {

struct RunRecord {
  std::uint64_t seed = 0;
  bool success = false;
  double length = std::numeric_limits<double>::infinity();  // cells
  double cost = std::numeric_limits<double>::infinity();    // PlanResult::cost (the length on a binary map)
  double smoothed_length = std::numeric_limits<double>::infinity();  // cells, along smoothed_path
  double total_turn_deg = 0.0;
  int iterations_to_converge = 0;  // iteration that first reached the final length (0 for A*)
  int iterations_run = 0;
  long long lost_ants_total = 0;
  bool stopped_early = false;      // early_stop_iterations without improvement
  bool interrupted = false;        // a time budget stopped it
  bool route_from_search = false;  // no ant arrived: eaci::plan returned the search route (success is false)
  double time_ms = 0.0;            // wall time around eaci::plan()
  double cpu_ms = 0.0;             // CPU time of the process (all its threads) around eaci::plan()
  double time_to_best_ms = 0.0;    // wall time until the iteration that found the final route ended
  double first_iteration_ms = 0.0; // wall time until the first iteration ended (set-up included)
  std::vector<double> best_length_so_far;
  std::vector<double> iteration_best_length;
  std::vector<int> lost_ants_per_iteration;
  std::vector<double> iteration_end_ms;  // wall time at the end of each iteration
  eaci::CellPath path;
  eaci::CellPath smoothed_path;    // PlanResult::smoothed_path (= path without smooth_path)
  std::vector<eaci::Cell> islands;
};

// Every field under its own name (cells as [row, col]); a non-finite number comes out as null.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(RunRecord, seed, success, length, cost, smoothed_length,
                                                total_turn_deg,
                                                iterations_to_converge, iterations_run, lost_ants_total,
                                                stopped_early, interrupted, route_from_search, time_ms, cpu_ms, time_to_best_ms,
                                                first_iteration_ms, best_length_so_far, iteration_best_length,
                                                lost_ants_per_iteration, iteration_end_ms, path, smoothed_path,
                                                islands)

// The per-iteration curves and the cells only when asked (they dominate the size); the
// smoothed route only when it differs from the route.
nlohmann::json toJson(const RunRecord& run, bool with_curves, bool with_path);
// Reads toJson's output back (null as +infinity; fields it left out keep their defaults).
RunRecord runRecordFromJson(nlohmann::json j);

}  // namespace eaci_bench
