// One timed plan as the benchmarks record it: the PlanResult's numbers, wall times and curves.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "eaci/grid/cell.hpp"

namespace eaci_bench {

struct RunRecord {
  std::uint64_t seed = 0;
  bool success = false;
  double length = std::numeric_limits<double>::infinity();  // cells
  double total_turn_deg = 0.0;
  int iterations_to_converge = 0;  // iteration that first reached the final length (0 for A*)
  int iterations_run = 0;
  long long lost_ants_total = 0;
  bool stopped_early = false;      // early_stop_iterations without improvement
  bool interrupted = false;        // a time budget stopped it
  double time_ms = 0.0;            // wall time around eaci::plan()
  double cpu_ms = 0.0;             // CPU time of the process (all its threads) around eaci::plan()
  double time_to_best_ms = 0.0;    // wall time until the iteration that found the final route ended
  double first_iteration_ms = 0.0; // wall time until the first iteration ended (set-up included)
  std::vector<double> best_length_so_far;
  std::vector<double> iteration_best_length;
  std::vector<int> lost_ants_per_iteration;
  std::vector<double> iteration_end_ms;  // wall time at the end of each iteration
  eaci::CellPath path;
  std::vector<eaci::Cell> islands;
};

// [[row, col], ...]
nlohmann::json cellsToJson(const std::vector<eaci::Cell>& cells);
std::vector<eaci::Cell> cellsFromJson(const nlohmann::json& j);

// Every field; the per-iteration curves and the cells only when asked (they dominate the size).
nlohmann::json toJson(const RunRecord& run, bool with_curves, bool with_path);
RunRecord runRecordFromJson(const nlohmann::json& j);

}  // namespace eaci_bench
