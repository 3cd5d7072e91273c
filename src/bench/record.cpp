#include "record.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "common/json_number.hpp"
#include "common/parameters_json.hpp"
#include "source_state.hpp"  // generated at build time (cmake/source_state.cmake)

namespace eaci_bench {

namespace {

using eaci::report::finiteOrNull;

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

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The value after "key:" on the first line of a /proc file that starts with `key` (no key: the first line).
std::string procValue(const char* file, const std::string& key) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key, 0) == 0) return key.empty() ? line : line.substr(line.find_first_not_of(" \t", line.find(':') + 1));
  return "unknown";
}

}  // namespace

nlohmann::json timedPlan(const TimedPlanRequest& request, bool with_curves, bool with_path) {
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
  const eaci::PlanResult r = eaci::plan(request.view, request.start, request.goal, request.algorithm, request.params, options);
  const double total_ms = millisecondsSince(start);
  const double cpu_ms = processCpuMilliseconds() - cpu_start;

  const auto best = static_cast<std::size_t>(std::max(r.iterations_to_converge, 0));
  nlohmann::json run = {
      // A route the colony did not find (geodesic EACI's fallback to its search route) is no success here.
      {"success", r.success() && !r.route_from_search}, {"route_from_search", r.route_from_search},
      {"length", finiteOrNull(r.length)}, {"cost", finiteOrNull(r.cost)}, {"combined_cost", finiteOrNull(r.combined_cost)},
      {"smoothed_length", finiteOrNull(r.smoothed_length)}, {"total_turn_deg", r.total_turn_deg},
      {"iterations_to_converge", r.iterations_to_converge}, {"iterations_run", r.iterations_run},
      {"lost_ants_total", r.lost_ants_total}, {"stopped_early", r.stopped_early}, {"interrupted", r.interrupted},
      {"time_ms", total_ms}, {"cpu_ms", cpu_ms},
      {"time_to_best_ms", best >= 1 && best <= iteration_end_ms.size() ? iteration_end_ms[best - 1] : total_ms},
      {"first_iteration_ms", iteration_end_ms.empty() ? total_ms : iteration_end_ms.front()}};
  if (with_curves) {
    run["best_cost_so_far"] = finiteOrNull(r.best_cost_so_far);
    run["iteration_best_cost"] = finiteOrNull(r.iteration_best_cost);
    run["lost_ants_per_iteration"] = r.lost_ants_per_iteration;
    run["iteration_end_ms"] = iteration_end_ms;
  }
  if (with_path) {
    run["path"] = r.path;
    if (r.smoothed_path != r.path) run["smoothed_path"] = r.smoothed_path;
    run["islands"] = r.islands;
  }
  return run;
}

nlohmann::json timedPlanMedian(const TimedPlanRequest& request, int repeats, bool with_path) {
  nlohmann::json run = timedPlan(request, false, with_path);
  std::vector<double> times = {run["time_ms"].get<double>()}, cpu_times = {run["cpu_ms"].get<double>()};
  for (int k = 1; k < repeats; ++k) {
    const nlohmann::json again = timedPlan(request, false, false);
    times.push_back(again["time_ms"].get<double>());
    cpu_times.push_back(again["cpu_ms"].get<double>());
  }
  run["time_ms"] = run["time_to_best_ms"] = median(times);
  run["cpu_ms"] = median(cpu_times);
  return run;
}

eaci::CellPath routeOf(const nlohmann::json& run, bool smoothed) {
  return (smoothed && run.contains("smoothed_path") ? run["smoothed_path"] : run["path"]).get<eaci::CellPath>();
}

nlohmann::json pheromoneSnapshots(const TimedPlanRequest& request, const std::vector<int>& iterations) {
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
          {"cpu_model", procValue("/proc/cpuinfo", "model name")},
          {"hardware_threads", std::thread::hardware_concurrency()},
          {"memory_gb", std::atof(procValue("/proc/meminfo", "MemTotal").c_str()) / (1024.0 * 1024.0)},
          {"date_utc", date},
          {"load_average_at_start", std::atof(procValue("/proc/loadavg", "").c_str())},
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
                               {"variant", r.variant},        {"seed", r.params.seed},
                               {"problem", r.problem},        {"parameters", params},
                               {"run", r.run},
                               {"extra", r.extra.is_null() ? nlohmann::json::object() : r.extra}, {"provenance", provenance_}};
  out_ << line.dump() << '\n';
  if (!out_) throw std::runtime_error("error while writing " + path_);
}

}  // namespace eaci_bench
