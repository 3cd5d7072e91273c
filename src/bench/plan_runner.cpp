#include "plan_runner.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>

namespace eaci_bench {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of the whole process (every thread), ms: unlike wall time, hardly affected by
// other programs sharing the cores.
double processCpuMilliseconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

RunRecord recordFrom(const eaci::PlanResult& result, const eaci::Parameters& params) {
  RunRecord run;
  run.seed = params.seed;
  // A route the colony did not find (geodesic EACI's fallback to its search route) is no success here.
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
  run.best_length_so_far = result.best_cost_so_far;
  run.iteration_best_length = result.iteration_best_cost;
  run.lost_ants_per_iteration = result.lost_ants_per_iteration;
  run.path = result.path;
  run.smoothed_path = result.smoothed_path;
  run.islands = result.islands;
  return run;
}

}  // namespace

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
  if (request.budget_ms > 0) {
    options.should_stop = [&](int) { return millisecondsSince(start) > request.budget_ms; };
  }
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

std::vector<PheromoneSnapshot> pheromoneSnapshots(const PlanRequest& request, const std::vector<int>& iterations) {
  std::vector<PheromoneSnapshot> snapshots;
  eaci::PlanOptions options;
  options.observer = [&](int iteration, const eaci::PheromoneField& field, const eaci::ColonyRegion& region) {
    if (std::find(iterations.begin(), iterations.end(), iteration) == iterations.end()) return;
    PheromoneSnapshot snapshot;
    snapshot.iteration = iteration;
    snapshot.strongest = eaci::strongestPheromoneByGridCell(field, region);
    snapshots.push_back(std::move(snapshot));
  };
  eaci::plan(request.view, request.start, request.goal, request.algorithm, request.params, options);
  return snapshots;
}

}  // namespace eaci_bench
