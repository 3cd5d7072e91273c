#include "record.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "common/json_number.hpp"
#include "common/parameters_json.hpp"
#include "source_state.hpp"  // generated at build time (cmake/source_state.cmake)

namespace eaci_bench {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of the whole process (every thread), ms: hardly affected by other programs on the cores.
double processCpuMilliseconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

RunRecord recordFrom(const eaci::PlanResult& result, const eaci::Parameters& params) {
  RunRecord run;
  run.seed = params.seed;
  run.success = result.success() && !result.route_from_search;
  run.route_from_search = result.route_from_search;
  run.length = result.length;
  run.cost = result.cost;
  run.smoothed_length = result.smoothed_length;
  run.total_turn_deg = result.total_turn_deg;
  run.iterations_to_converge = result.iterations_to_converge;
  run.iterations_run = result.iterations_run;
  run.lost_ants_total = result.lost_ants_total;
  run.stopped_early = result.stopped_early;
  run.interrupted = result.interrupted;
  run.best_cost_so_far = result.best_length_so_far;         // B2: best_cost_so_far
  run.iteration_best_cost = result.iteration_best_length;   // B2: iteration_best_cost
  run.lost_ants_per_iteration = result.lost_ants_per_iteration;
  run.path = result.path;
  run.smoothed_path = result.smoothed_path;
  run.islands = result.islands;
  return run;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string firstValue(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

double firstNumber(const char* file, bool skip_key) {
  std::ifstream in(file);
  std::string key;
  double value = 0.0;
  if (skip_key) in >> key;
  in >> value;
  return value;
}

}  // namespace

nlohmann::json toJson(const RunRecord& run, bool with_curves, bool with_path) {
  nlohmann::json j = run;
  if (!with_curves)
    for (const char* key : {"best_cost_so_far", "iteration_best_cost", "lost_ants_per_iteration", "iteration_end_ms"})
      j.erase(key);
  if (!with_path)
    for (const char* key : {"path", "smoothed_path", "islands"}) j.erase(key);
  else if (run.smoothed_path == run.path)
    j.erase("smoothed_path");
  return j;
}

RunRecord runRecordFromJson(nlohmann::json j) {
  eaci::report::nullsToInfinity(j);
  RunRecord run = j.get<RunRecord>();
  if (!j.contains("smoothed_path")) run.smoothed_path = run.path;
  return run;
}

RunRecord timedPlan(const PlanRequest& request) {
  std::vector<double> iteration_end_ms;
  iteration_end_ms.reserve(static_cast<std::size_t>(request.params.max_iterations));
  eaci::PlanOptions options;
  options.workspace = request.workspace;
  const double cpu_start = processCpuMilliseconds();
  const Clock::time_point start = Clock::now();
  options.observer = [&](int iteration, const eaci::PheromoneField&, const eaci::ColonyRegion&) {
    if (iteration > 0) iteration_end_ms.push_back(millisecondsSince(start));
  };
  if (request.budget_ms > 0) options.should_stop = [&](int) { return millisecondsSince(start) > request.budget_ms; };
  const eaci::PlanResult result =
      eaci::plan(request.view, request.start, request.goal, request.algorithm, request.params, options);
  const double total_ms = millisecondsSince(start);
  const double cpu_ms = processCpuMilliseconds() - cpu_start;

  RunRecord run = recordFrom(result, request.params);
  run.time_ms = total_ms;
  run.cpu_ms = cpu_ms;
  run.iteration_end_ms = std::move(iteration_end_ms);
  const auto best = static_cast<std::size_t>(std::max(run.iterations_to_converge, 0));
  run.time_to_best_ms = best >= 1 && best <= run.iteration_end_ms.size() ? run.iteration_end_ms[best - 1] : total_ms;
  run.first_iteration_ms = run.iteration_end_ms.empty() ? total_ms : run.iteration_end_ms.front();
  return run;
}

RunRecord timedPlanMedian(const PlanRequest& request, int repeats) {
  RunRecord record = timedPlan(request);
  std::vector<double> times = {record.time_ms}, cpu_times = {record.cpu_ms};
  for (int k = 1; k < repeats; ++k) {
    const RunRecord again = timedPlan(request);
    times.push_back(again.time_ms);
    cpu_times.push_back(again.cpu_ms);
  }
  record.time_ms = record.time_to_best_ms = median(times);
  record.cpu_ms = median(cpu_times);
  return record;
}

nlohmann::json pheromoneSnapshots(const PlanRequest& request, const std::vector<int>& iterations) {
  nlohmann::json snapshots = nlohmann::json::array();
  eaci::PlanOptions options;
  options.observer = [&](int iteration, const eaci::PheromoneField& field, const eaci::ColonyRegion& region) {
    if (std::find(iterations.begin(), iterations.end(), iteration) == iterations.end()) return;
    snapshots.push_back({{"iteration", iteration}, {"strongest", eaci::strongestPheromoneByGridCell(field, region)}});
  };
  eaci::plan(request.view, request.start, request.goal, request.algorithm, request.params, options);
  return snapshots;
}

nlohmann::json provenance(const std::string& command_line) {
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
#if defined(__clang__)
  const std::string compiler = std::string("clang ") + __clang_version__;
#else
  const std::string compiler = std::string("g++ ") + __VERSION__;
#endif
#ifdef NDEBUG
  const char* build_type = "optimised (NDEBUG)";
#else
  const char* build_type = "assertions on (no NDEBUG)";
#endif
  return {{"git_commit", source_state::kCommit},
          {"git_dirty", source_state::kDirty},
          {"modified_solver_sources", source_state::kModifiedSolverSources},
          {"compiler", compiler},
          {"build_type", build_type},
          {"cpu_model", firstValue("/proc/cpuinfo", "model name")},
          {"hardware_threads", std::thread::hardware_concurrency()},
          {"memory_gb", firstNumber("/proc/meminfo", true) / (1024.0 * 1024.0)},
          {"date_utc", date},
          {"load_average_at_start", firstNumber("/proc/loadavg", false)},
          {"command_line", command_line}};
}

RecordWriter::RecordWriter(const std::string& out_dir, const std::string& command, const std::string& command_line)
    : command_(command), path_(out_dir + "/" + command + ".jsonl"), provenance_(provenance(command_line)),
      defaults_(eaci::report::parametersToJson(eaci::Parameters{})) {
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) throw std::runtime_error("cannot create directory " + out_dir + ": " + error.message());
  out_.open(path_, std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot write " + path_);
}

void RecordWriter::append(const Record& r) {
  nlohmann::json params = nlohmann::json::object();  // what differs from the defaults (seed: the record's own)
  const nlohmann::json all = eaci::report::parametersToJson(r.params);
  for (const auto& [key, value] : all.items())
    if (key != "seed" && value != defaults_[key]) params[key] = value;
  const nlohmann::json line = {{"command", command_},         {"map", r.map},
                               {"variant", r.variant},        {"seed", r.run.seed},
                               {"problem", r.problem},        {"parameters", params},
                               {"run", toJson(r.run, r.with_curves, r.with_path)},
                               {"extra", r.extra.is_null() ? nlohmann::json::object() : r.extra}, {"provenance", provenance_}};
  out_ << line.dump() << '\n';
  if (!out_) throw std::runtime_error("error while writing " + path_);
}

}  // namespace eaci_bench
