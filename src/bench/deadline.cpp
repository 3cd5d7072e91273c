#include "deadline.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "forked_run.hpp"
#include "plan_runner.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report_format.hpp"
#include "statistics.hpp"

namespace eaci_bench {

namespace {

struct DeadlineRun {
  MapKind kind = MapKind::kRooms;
  int size = 0;
  std::uint64_t seed = 0;
  std::size_t limit_index = 0;  // in DeadlineOptions::limits_s: the report groups runs by it
  double limit_ms = 0.0;
  RunRecord record;
  double optimum = 0.0;
};

// One plan in a child process: EACI, default parameters, iterations enough to outlast any
// limit, early stopping off, stopped by the wall clock.
DeadlineRun runOne(const GeneratedMap& g, const DeadlineOptions& options, std::size_t limit_index) {
  const double limit_s = options.limits_s[limit_index];
  eaci::Parameters params;
  params.seed = g.seed;
  params.threads = options.threads;
  params.max_iterations = 1000000;
  params.early_stop_iterations = 0;
  const PlanRequest request{g.map.view(), g.start, g.goal, eaci::Algorithm::kEaci, params, limit_s * 1000.0};
  const ForkedResult child = runForked([&] { return toJson(timedPlan(request), false, false).dump(); });
  if (!child.ok) throw std::runtime_error("deadline run on " + std::string(toString(g.kind)) + " " +
                                          std::to_string(g.size) + ": " + child.error);
  DeadlineRun run;
  run.kind = g.kind;
  run.size = g.size;
  run.seed = g.seed;
  run.limit_index = limit_index;
  run.limit_ms = limit_s * 1000.0;
  run.record = runRecordFromJson(nlohmann::json::parse(child.output));
  run.optimum = g.optimum;
  return run;
}

double overshootPct(const DeadlineRun& r) { return (r.record.time_ms / r.limit_ms - 1.0) * 100.0; }

std::string markdown(const DeadlineOptions& options, const Provenance& provenance, const std::vector<DeadlineRun>& runs) {
  std::ostringstream s;
  s << "## Planning-time limit: wall time of a plan against `max_planning_time`\n\n"
    << provenanceMarkdown(provenance) << "\n"
    << "EACI with default parameters (geodesic islands, corner cutting forbidden), " << options.threads
    << " thread(s), Nc_max = 1,000,000 and early stopping off, so that only the limit ends the run; "
       "the limit is checked as the ROS node and plugin check `max_planning_time` (wall clock since the call, "
       "asked between EACI's set-up steps and between iterations). Each plan runs in its own child process. "
       "*wall*: median / worst wall time of `eaci::plan()` over the map seeds; *over*: worst wall time over "
       "the limit; *routes*: plans that returned a route; *gap*: average length over the A* optimum; "
       "*set-up + 1st iteration*: median wall time until the first iteration ended.\n\n";
  MarkdownTable table({"map", "limit s", "wall median ms", "wall worst ms", "over (worst)", "routes", "iterations run",
                       "gap avg %", "set-up + 1st iteration ms"});
  for (MapKind kind : options.kinds)
    for (int size : options.sizes)
      for (std::size_t limit_index = 0; limit_index < options.limits_s.size(); ++limit_index) {
        std::vector<double> walls, firsts, gaps;
        double worst_over = -1e9, iterations = 0.0;
        int routes = 0, n = 0;
        for (const DeadlineRun& r : runs) {
          if (r.kind != kind || r.size != size || r.limit_index != limit_index) continue;
          ++n;
          walls.push_back(r.record.time_ms);
          firsts.push_back(r.record.first_iteration_ms);
          worst_over = std::max(worst_over, overshootPct(r));
          iterations += r.record.iterations_run;
          if (r.record.success) {
            ++routes;
            gaps.push_back((r.record.length / r.optimum - 1.0) * 100.0);
          }
        }
        if (n == 0) continue;
        table.addRow({std::string(toString(kind)) + " " + std::to_string(size), fixed(options.limits_s[limit_index], 2),
                      fixed(median(walls), 1),
                      fixed(*std::max_element(walls.begin(), walls.end()), 1),
                      (worst_over >= 0 ? "+" : "") + fixed(worst_over, 1) + " %",
                      std::to_string(routes) + "/" + std::to_string(n), fixed(iterations / n, 0),
                      gaps.empty() ? "—" : fixed(mean(gaps), 2), fixed(median(firsts), 1)});
      }
  s << table.render();
  return s.str();
}

nlohmann::json toJson(const DeadlineOptions& options, const Provenance& provenance, const std::vector<DeadlineRun>& runs) {
  nlohmann::json rows = nlohmann::json::array();
  for (const DeadlineRun& r : runs)
    rows.push_back({{"kind", toString(r.kind)}, {"size", r.size}, {"seed", r.seed}, {"limit_ms", r.limit_ms},
                    {"optimum", r.optimum}, {"overshoot_pct", overshootPct(r)}, {"run", eaci_bench::toJson(r.record, false, false)}});
  return {{"provenance", provenance}, {"threads", options.threads}, {"runs", rows}};
}

std::string csv(const std::vector<DeadlineRun>& runs) {
  CsvTable table({"kind", "size", "seed", "limit_ms", "time_ms", "overshoot_pct", "success", "length", "optimum",
                  "iterations_run", "first_iteration_ms"});
  for (const DeadlineRun& r : runs)
    table.addRow({toString(r.kind), std::to_string(r.size), std::to_string(r.seed), csvNumber(r.limit_ms),
                  csvNumber(r.record.time_ms), csvNumber(overshootPct(r)), r.record.success ? "1" : "0",
                  csvNumber(r.record.length), csvNumber(r.optimum), std::to_string(r.record.iterations_run),
                  csvNumber(r.record.first_iteration_ms)});
  return table.render();
}

}  // namespace

int runDeadlineCommand(const DeadlineOptions& options) {
  const Provenance provenance = collectProvenance(options.command_line);
  Progress progress("deadline");
  std::vector<DeadlineRun> runs;
  for (MapKind kind : options.kinds)
    for (int size : options.sizes)
      for (int k = 1; k <= options.runs; ++k) {
        const GeneratedMap g = generateMap(kind, size, static_cast<std::uint64_t>(k));
        for (std::size_t limit_index = 0; limit_index < options.limits_s.size(); ++limit_index) {
          std::ostringstream label;
          label << toString(kind) << " " << size << " | limit " << options.limits_s[limit_index] << " s";
          progress.show(label.str(), k, options.runs);
          runs.push_back(runOne(g, options, limit_index));
        }
      }
  progress.finish();
  writeReport(options.out_dir, "deadline",
              {toJson(options, provenance, runs), csv(runs), markdown(options, provenance, runs), {}});
  return 0;
}

}  // namespace eaci_bench
