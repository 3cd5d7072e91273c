#include "scen.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>

#include "eaci/io/map_io.hpp"
#include "plan_runner.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report_format.hpp"
#include "scen_report.hpp"
#include "statistics.hpp"

namespace eaci_bench {

namespace {

namespace fs = std::filesystem;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// "[#####.....]" for k of n.
std::string bar(std::size_t k, std::size_t n, int width = 20) {
  const auto filled = n == 0 ? 0 : static_cast<int>(static_cast<double>(k) / static_cast<double>(n) * width);
  return "[" + std::string(static_cast<std::size_t>(filled), '#') + std::string(static_cast<std::size_t>(width - filled), '.') + "]";
}

std::string where(const ScenOptions& o, const eaci::ScenarioProblem& p) {
  return o.scen_path + ": line " + std::to_string(p.line) + ": ";
}

// The problem fits its map: sizes as written, start and goal on the map and passable.
void checkProblem(const ScenOptions& o, const eaci::ScenarioProblem& p, const eaci::OccupancyMap& map,
                  const std::string& map_path) {
  if (p.map_width != map.width || p.map_height != map.height) {
    throw std::runtime_error(where(o, p) + "map size " + std::to_string(p.map_width) + " x " +
                             std::to_string(p.map_height) + " but " + map_path + " is " + std::to_string(map.width) +
                             " x " + std::to_string(map.height));
  }
  const eaci::GridView view = map.view();
  for (const auto& [name, cell] : {std::pair<const char*, eaci::Cell>{"start", p.start}, {"goal", p.goal}}) {
    if (cell.row >= map.height || cell.col >= map.width)
      throw std::runtime_error(where(o, p) + name + " (x " + std::to_string(cell.col) + ", y " + std::to_string(cell.row) +
                               ") is off the map");
    if (!view.isFree(cell))
      throw std::runtime_error(where(o, p) + name + " (x " + std::to_string(cell.col) + ", y " + std::to_string(cell.row) +
                               ") is blocked in " + map_path);
  }
}

double gapPct(double length, double optimum) {
  if (!std::isfinite(length)) return kInfinity;
  if (optimum <= 0.0) return length <= kScenMismatchTolerance ? 0.0 : kInfinity;
  return (length / optimum - 1.0) * 100.0;
}

void summarizeProblem(ScenProblemResult& r) {
  const double optimum = r.problem.optimal_length;
  r.astar_diff = r.astar.success ? r.astar.length - optimum : kInfinity;
  r.mismatch = !(std::abs(r.astar_diff) <= kScenMismatchTolerance);
  std::vector<double> lengths, gaps, times;
  for (const RunRecord& run : r.eaci) {
    times.push_back(run.time_ms);
    if (!run.success) continue;
    lengths.push_back(run.length);
    gaps.push_back(gapPct(run.length, optimum));
  }
  r.eaci_successes = static_cast<int>(lengths.size());
  r.eaci_length = lengths.empty() ? kInfinity : mean(lengths);
  r.eaci_gap_pct = gaps.empty() ? kInfinity : mean(gaps);
  r.eaci_worst_gap_pct = gaps.empty() ? kInfinity : *std::max_element(gaps.begin(), gaps.end());
  r.eaci_time_ms = median(times);
  r.time_ratio = r.astar.time_ms > 0.0 ? r.eaci_time_ms / r.astar.time_ms : kInfinity;
}

class ScenRunner {
 public:
  explicit ScenRunner(const ScenOptions& options) : options_(options), progress_("scen") {}

  ScenResult run() {
    const std::vector<eaci::ScenarioProblem> problems = eaci::loadMovingAiScenario(options_.scen_path);
    std::vector<std::size_t> chosen;
    for (std::size_t k = 0; k < problems.size(); k += static_cast<std::size_t>(options_.every)) chosen.push_back(k);
    ScenResult result;
    for (std::size_t n = 0; n < chosen.size(); ++n) {
      const eaci::ScenarioProblem& p = problems[chosen[n]];
      progress_.show(bar(n + 1, chosen.size()) + " problem " + std::to_string(chosen[n] + 1) + " (bucket " +
                         std::to_string(p.bucket) + ", " + p.map + ")",
                     static_cast<int>(n + 1), static_cast<int>(chosen.size()));
      result.problems.push_back(runProblem(chosen[n], p));
      if (result.problems.back().mismatch) noteMismatch(result.problems.back());
    }
    progress_.finish();
    result.summary = summarizeScenario(result.problems, problems.size());
    result.summary.wall_s = progress_.elapsedSeconds();
    return result;
  }

 private:
  std::string mapPath(const std::string& name) const {
    const fs::path dir = options_.map_dir.empty() ? fs::path(options_.scen_path).parent_path() : fs::path(options_.map_dir);
    return (dir / name).string();
  }

  const eaci::OccupancyMap& map(const std::string& path) {
    auto found = maps_.find(path);
    if (found == maps_.end()) found = maps_.emplace(path, eaci::loadMap(path)).first;
    return found->second;
  }

  ScenProblemResult runProblem(std::size_t index, const eaci::ScenarioProblem& p) {
    ScenProblemResult r;
    r.index = index;
    r.problem = p;
    r.map_path = mapPath(p.map);
    const eaci::OccupancyMap& m = map(r.map_path);
    checkProblem(options_, p, m, r.map_path);
    eaci::Parameters params = options_.parameters;  // the defaults or --params; corner cutting forbidden
    // Each planner keeps its buffers and threads from plan to plan, as a robot's planner would.
    r.astar = timedPlan(PlanRequest{m.view(), p.start, p.goal, eaci::Algorithm::kAStar, params, 0.0, &astar_workspace_});
    for (int seed = 1; seed <= options_.seeds; ++seed) {
      params.seed = static_cast<std::uint64_t>(seed);
      r.eaci.push_back(timedPlan(PlanRequest{m.view(), p.start, p.goal, eaci::Algorithm::kEaci, params,
                                             options_.budget_s * 1000.0, &eaci_workspace_}));
    }
    summarizeProblem(r);
    return r;
  }

  void noteMismatch(const ScenProblemResult& r) {
    progress_.note("mismatch on problem " + std::to_string(r.index + 1) + " (line " + std::to_string(r.problem.line) +
                   "): optimal length " + fixed(r.problem.optimal_length, 6) + ", A* " +
                   (r.astar.success ? fixed(r.astar.length, 6) : std::string("no route")));
  }

  const ScenOptions& options_;
  Progress progress_;
  eaci::PlannerWorkspace astar_workspace_, eaci_workspace_;
  std::map<std::string, eaci::OccupancyMap> maps_;
};

}  // namespace

ScenSummary summarizeScenario(const std::vector<ScenProblemResult>& problems, std::size_t problems_in_file) {
  ScenSummary s;
  s.problems_in_file = problems_in_file;
  s.problems_run = problems.size();
  std::vector<double> problem_gaps, ratios;
  double gap_sum = 0.0;
  s.worst_gap_pct = problems.empty() ? 0.0 : -kInfinity;
  for (const ScenProblemResult& r : problems) {
    s.mismatches += r.mismatch;
    s.astar_failures += !r.astar.success;
    s.astar_total_ms += r.astar.time_ms;
    for (const RunRecord& run : r.eaci) {
      ++s.eaci_runs;
      s.eaci_total_ms += run.time_ms;
      if (!run.success) {
        ++s.eaci_failures;
        continue;
      }
      const double gap = gapPct(run.length, r.problem.optimal_length);
      s.worst_gap_pct = std::max(s.worst_gap_pct, gap);
      s.eaci_optimal_runs += std::abs(run.length - r.problem.optimal_length) <= kScenMismatchTolerance;
    }
    if (r.eaci_successes > 0) {
      problem_gaps.push_back(r.eaci_gap_pct);
      gap_sum += r.eaci_gap_pct;
    }
    if (std::isfinite(r.time_ratio)) ratios.push_back(r.time_ratio);
  }
  if (s.worst_gap_pct == -kInfinity) s.worst_gap_pct = kInfinity;  // no successful run at all
  s.median_gap_pct = problem_gaps.empty() ? kInfinity : median(problem_gaps);
  s.mean_gap_pct = problem_gaps.empty() ? kInfinity : gap_sum / static_cast<double>(problem_gaps.size());
  s.median_time_ratio = ratios.empty() ? kInfinity : median(ratios);
  return s;
}

ScenResult runScenario(const ScenOptions& options) { return ScenRunner(options).run(); }

int runScenCommand(const ScenOptions& options) {
  const Provenance provenance = collectProvenance(options.command_line);
  const ScenResult result = runScenario(options);
  writeReport(options.out_dir, "scen",
              {scenJson(result, options, provenance), scenCsv(result), scenMarkdown(result, options, provenance), {}});
  std::cout << scenSummaryLine(result.summary) << "\n";
  return result.summary.mismatches > 0 ? 1 : 0;
}

}  // namespace eaci_bench
