#include "run_record.hpp"

#include <cmath>

#include "common/json_number.hpp"

namespace eaci_bench {

namespace {

using eaci::report::finiteOrNull;

// Non-finite numbers are written as null (finiteOrNull); null is read back as +infinity.
double numberFrom(const nlohmann::json& j) {
  return j.is_null() ? std::numeric_limits<double>::infinity() : j.get<double>();
}

std::vector<double> numbersFrom(const nlohmann::json& j) {
  std::vector<double> out;
  for (const auto& v : j) out.push_back(numberFrom(v));
  return out;
}

}  // namespace

nlohmann::json cellsToJson(const std::vector<eaci::Cell>& cells) {
  nlohmann::json out = nlohmann::json::array();
  for (const eaci::Cell& c : cells) out.push_back({c.row, c.col});
  return out;
}

std::vector<eaci::Cell> cellsFromJson(const nlohmann::json& j) {
  std::vector<eaci::Cell> out;
  for (const auto& c : j) out.push_back(eaci::Cell{c.at(0).get<int>(), c.at(1).get<int>()});
  return out;
}

nlohmann::json toJson(const RunRecord& run, bool with_curves, bool with_path) {
  nlohmann::json j = {
      {"seed", run.seed},
      {"success", run.success},
      {"length", finiteOrNull(run.length)},
      {"total_turn_deg", run.total_turn_deg},
      {"iterations_to_converge", run.iterations_to_converge},
      {"iterations_run", run.iterations_run},
      {"lost_ants_total", run.lost_ants_total},
      {"stopped_early", run.stopped_early},
      {"interrupted", run.interrupted},
      {"time_ms", run.time_ms},
      {"cpu_ms", run.cpu_ms},
      {"time_to_best_ms", run.time_to_best_ms},
      {"first_iteration_ms", run.first_iteration_ms},
  };
  if (with_curves) {
    j["best_length_so_far"] = finiteOrNull(run.best_length_so_far);
    j["iteration_best_length"] = finiteOrNull(run.iteration_best_length);
    j["lost_ants_per_iteration"] = run.lost_ants_per_iteration;
    j["iteration_end_ms"] = run.iteration_end_ms;
  }
  if (with_path) {
    j["path"] = cellsToJson(run.path);
    j["islands"] = cellsToJson(run.islands);
  }
  return j;
}

RunRecord runRecordFromJson(const nlohmann::json& j) {
  RunRecord run;
  run.seed = j.at("seed").get<std::uint64_t>();
  run.success = j.at("success").get<bool>();
  run.length = numberFrom(j.at("length"));
  run.total_turn_deg = j.at("total_turn_deg").get<double>();
  run.iterations_to_converge = j.at("iterations_to_converge").get<int>();
  run.iterations_run = j.at("iterations_run").get<int>();
  run.lost_ants_total = j.at("lost_ants_total").get<long long>();
  run.stopped_early = j.at("stopped_early").get<bool>();
  run.interrupted = j.at("interrupted").get<bool>();
  run.time_ms = j.at("time_ms").get<double>();
  run.cpu_ms = j.at("cpu_ms").get<double>();
  run.time_to_best_ms = j.at("time_to_best_ms").get<double>();
  run.first_iteration_ms = j.at("first_iteration_ms").get<double>();
  if (j.contains("best_length_so_far")) {
    run.best_length_so_far = numbersFrom(j.at("best_length_so_far"));
    run.iteration_best_length = numbersFrom(j.at("iteration_best_length"));
    run.lost_ants_per_iteration = j.at("lost_ants_per_iteration").get<std::vector<int>>();
    run.iteration_end_ms = j.at("iteration_end_ms").get<std::vector<double>>();
  }
  if (j.contains("path")) {
    run.path = cellsFromJson(j.at("path"));
    run.islands = cellsFromJson(j.at("islands"));
  }
  return run;
}

}  // namespace eaci_bench
