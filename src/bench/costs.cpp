#include "costs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "costs_report.hpp"
#include "eaci/io/map_io.hpp"
#include "forked_run.hpp"
#include "plan_runner.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report_format.hpp"

namespace eaci_bench {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kMaxMapAttempts = 100;

// A map to plan on: its inflated costs, the grids the checks read, start and goal.
struct PreparedMap {
  CostBytes costs;
  eaci::GridView view;          // over costs.bytes, read as the planners read a costmap
  eaci::CostGrid planning;      // >= 253 blocked, the rest weighted
  eaci::CostGrid obstacles;     // the map's own obstacles (clearance)
};

void prepare(PreparedMap& m, const eaci::OccupancyMap& map, const eaci::InflationParameters& inflation,
             double resolution) {
  const eaci::Parameters defaults;
  const eaci::UnknownPolicy unknown = defaults.allow_unknown ? eaci::UnknownPolicy::kFree : eaci::UnknownPolicy::kObstacle;
  m.costs.width = map.width;
  m.costs.height = map.height;
  m.costs.bytes = eaci::inflatedCosts(map.view(unknown), resolution, inflation);
  m.view = eaci::GridView(m.costs.bytes.data(), map.width, map.height, eaci::RowOrder::kTopFirst,
                          eaci::inflatedCostsInterpretation(defaults.allow_unknown));
  m.planning = eaci::CostGrid::fromView(m.view, defaults.allow_corner_cutting, eaci::costRule(defaults));
  m.obstacles = eaci::CostGrid::fromView(map.view(unknown), defaults.allow_corner_cutting);
}

double blockedFraction(const CostBytes& costs) {
  const auto blocked = std::count_if(costs.bytes.begin(), costs.bytes.end(),
                                     [](std::uint8_t v) { return v >= eaci::kCostmapInscribedObstacle; });
  return costs.bytes.empty() ? 0.0 : static_cast<double>(blocked) / static_cast<double>(costs.bytes.size());
}

std::string metres(double x, double y) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.2f, %.2f)", x, y);
  return text;
}

class CostsRunner {
 public:
  explicit CostsRunner(const CostsOptions& options) : options_(options), progress_("costs") {}

  std::vector<CostGroup> run() {
    std::vector<CostGroup> groups;
    if (!options_.lab_map.empty()) groups.push_back(runLab());
    for (MapKind kind : options_.kinds)
      for (int size : options_.sizes) groups.push_back(runGenerated(kind, size));
    progress_.finish();
    return groups;
  }

 private:
  CostGroup runLab() {
    CostGroup group;
    group.name = "lab";
    group.lab = true;
    const eaci::OccupancyMap map = eaci::loadMap(options_.lab_map);
    group.size = map.width;
    group.resolution = map.resolution;
    PreparedMap prepared;
    prepare(prepared, map, options_.lab_inflation, map.resolution);
    const std::vector<LabPair> pairs = defaultLabPairs();
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const LabPair& pair = pairs[p];
      CostProblem problem;
      problem.name = metres(pair.start_x, pair.start_y) + " → " + metres(pair.goal_x, pair.goal_y) +
                     (pair.note.empty() ? "" : " " + pair.note);
      const auto start = map.worldToCell({pair.start_x, pair.start_y});
      const auto goal = map.worldToCell({pair.goal_x, pair.goal_y});
      if (!start || !goal || !prepared.planning.isFree(*start) || !prepared.planning.isFree(*goal))
        throw std::runtime_error("lab pair " + problem.name + ": start or goal off the map or in an inflated obstacle");
      problem.start = *start;
      problem.goal = *goal;
      solve(group, problem, prepared, options_.lab_seeds, /*keep_paths=*/true);
      if (p == 0) problem.example_costs = prepared.costs;
      group.problems.push_back(std::move(problem));
    }
    return group;
  }

  CostGroup runGenerated(MapKind kind, int size) {
    CostGroup group;
    group.name = std::string(toString(kind)) + " " + std::to_string(size);
    group.kind = kind;
    group.size = size;
    const int seeds = costsSeedsFor(size, options_.runs);
    std::set<std::uint64_t> used;  // generateMap moves to the next seed when one fails: no map twice
    for (int k = 1; k <= seeds; ++k) {
      GeneratedMap g;
      PreparedMap prepared;
      bool found = false;
      std::vector<std::uint64_t> redrawn;
      for (int attempt = 0; attempt < kMaxMapAttempts && !found; ++attempt) {
        g = generateMap(kind, size, static_cast<std::uint64_t>(k) + 10000ULL * static_cast<std::uint64_t>(attempt),
                        options_.generator);
        if (used.count(g.seed_used)) continue;
        prepare(prepared, g.map, options_.generated_inflation, 1.0);
        found = prepared.planning.isFree(g.start) && prepared.planning.isFree(g.goal) &&
                eaci::cheapestPath(prepared.planning, g.start, g.goal).found;
        if (!found) redrawn.push_back(g.seed_used);
      }
      if (!found) throw std::runtime_error("no connected inflated " + group.name + " map for seed " + std::to_string(k));
      if (!redrawn.empty()) {
        std::ostringstream note;
        note << "seed " << k << ": map seed" << (redrawn.size() > 1 ? "s " : " ");
        for (std::size_t i = 0; i < redrawn.size(); ++i) note << (i ? ", " : "") << redrawn[i];
        note << " had no route once inflated; used map seed " << g.seed_used;
        addNote(group, note.str());
      }
      used.insert(g.seed_used);
      CostProblem problem;
      problem.name = group.name + " seed " + std::to_string(g.seed_used);
      problem.map_seed = static_cast<std::uint64_t>(k);
      problem.map_seed_used = g.seed_used;
      problem.start = g.start;
      problem.goal = g.goal;
      problem.obstacle_fraction = g.obstacle_fraction;
      const bool example = k == 1 && size <= options_.example_max_size;
      solveOneSeed(group, problem, prepared, static_cast<std::uint64_t>(k), example);
      if (example) problem.example_costs = prepared.costs;
      group.problems.push_back(std::move(problem));
    }
    return group;
  }

  // Lab pairs: seeds 1..seeds on the same map.
  void solve(CostGroup& group, CostProblem& problem, const PreparedMap& prepared, int seeds, bool keep_paths) {
    startProblem(problem, prepared);
    for (int k = 1; k <= seeds; ++k) runSeed(group, problem, prepared, static_cast<std::uint64_t>(k), keep_paths && k == 1, k, seeds);
    finishProblem(group, problem);
  }

  // Generated maps: one seed per map.
  void solveOneSeed(CostGroup& group, CostProblem& problem, const PreparedMap& prepared, std::uint64_t seed, bool keep_paths) {
    startProblem(problem, prepared);
    runSeed(group, problem, prepared, seed, keep_paths, static_cast<int>(problem.map_seed), costsSeedsFor(group.size, options_.runs));
    finishProblem(group, problem);
  }

  void startProblem(CostProblem& problem, const PreparedMap& prepared) {
    problem.dijkstra_cost = dijkstraCost(prepared.costs, problem.start, problem.goal);
    problem.blocked_fraction = blockedFraction(prepared.costs);
    for (const CostVariant& v : costVariants()) problem.variants.push_back(CostVariantRuns{v, {}});
  }

  void runSeed(CostGroup& group, CostProblem& problem, const PreparedMap& prepared, std::uint64_t seed, bool keep_paths,
               int k, int n) {
    for (CostVariantRuns& v : problem.variants) {
      progress_.show(group.name + " | " + toString(v.variant.key), k, n);
      eaci::Parameters params;
      params.seed = seed;
      params.threads = 1;
      params.smooth_path = v.variant.smooth;
      const PlanRequest request{prepared.view, problem.start, problem.goal, v.variant.algorithm, params,
                                v.variant.algorithm == eaci::Algorithm::kAStar ? 0.0 : options_.budget_s * 1000.0};
      const ForkedResult child = runForked([&] { return toJson(timedPlan(request), false, true).dump(); });
      if (!child.ok) throw std::runtime_error(std::string(toString(v.variant.key)) + " on " + problem.name + ": " + child.error);
      CostRun run;
      run.record = runRecordFromJson(nlohmann::json::parse(child.output));
      run.peak_rss_mb = child.peak_rss_mb;
      if (run.record.success) run.driven = checkRoute(prepared.planning, prepared.obstacles, prepared.costs, run.record.smoothed_path);
      if (run.record.interrupted) addNote(group, problem.name + ": " + v.variant.label + " seed " + std::to_string(seed) +
                                                     " hit the " + fixed(options_.budget_s, 0) + " s budget (capped)");
      v.runs.push_back(std::move(run));
    }
    // Gaps and ratios against this seed's A* run; smoothed routes against their unsmoothed twin.
    const CostRun& astar = problem.variants.front().runs.back();
    for (CostVariantRuns& v : problem.variants) {
      CostRun& run = v.runs.back();
      run.time_ratio = astar.record.time_ms > 0 ? run.record.time_ms / astar.record.time_ms : kInfinity;
      run.gap_pct = run.record.success ? costGapPct(run.driven.cost, astar.record.cost) : kInfinity;
      if (v.variant.smooth)
        for (const CostVariantRuns& twin : problem.variants)
          if (!twin.variant.smooth && twin.variant.algorithm == v.variant.algorithm)
            run.same_grid_route = twin.runs.back().record.path == run.record.path;
    }
    if (!keep_paths)
      for (CostVariantRuns& v : problem.variants) {
        RunRecord& record = v.runs.back().record;
        record.path.clear();
        record.smoothed_path.clear();
        record.islands.clear();
      }
  }

  void finishProblem(CostGroup& group, CostProblem& problem) {
    const CostVariantRuns& astar = problem.variants.front();
    problem.astar_cost = astar.runs.empty() ? kInfinity : astar.runs.front().record.cost;
    if (!(std::abs(problem.astar_cost - problem.dijkstra_cost) <= 1e-6 * std::max(1.0, problem.dijkstra_cost)))
      addNote(group, problem.name + ": A* cost " + fixed(problem.astar_cost, 6) + " differs from Dijkstra's " +
                         fixed(problem.dijkstra_cost, 6));
    for (const CostVariantRuns& v : problem.variants)
      for (const CostRun& run : v.runs) {
        if (!run.record.success) addNote(group, problem.name + ": " + v.variant.label + " seed " + std::to_string(run.record.seed) + " found no route");
        if (run.driven.lethal_cells + run.driven.inscribed_cells > 0)
          addNote(group, problem.name + ": " + v.variant.label + " seed " + std::to_string(run.record.seed) + " enters " +
                             std::to_string(run.driven.lethal_cells) + " lethal and " +
                             std::to_string(run.driven.inscribed_cells) + " inscribed cells");
        if (v.variant.smooth && !run.same_grid_route)
          addNote(group, problem.name + ": " + v.variant.label + " seed " + std::to_string(run.record.seed) +
                             " smoothed a different grid route than its unsmoothed twin");
      }
  }

  void addNote(CostGroup& group, const std::string& note) {
    group.notes.push_back(note);
    progress_.note(group.name + ": " + note);
  }

  const CostsOptions& options_;
  Progress progress_;
};

}  // namespace

std::vector<LabPair> defaultLabPairs() {
  return {
      {0.4, 0.4, 4.4, 2.6, ""},
      {0.4, 0.4, 2.45, 1.5, "in the U"},
      {0.4, 0.4, 1.1, 2.2, "behind the L"},
      {0.4, 0.4, 4.2, 0.5, "past the cubes"},
      {0.4, 0.4, 0.5, 2.6, ""},
      {4.4, 2.6, 0.5, 2.6, "along the top"},
      {1.1, 2.2, 4.2, 0.5, "diagonal"},
      {2.45, 1.5, 4.4, 2.6, "out of the U"},
  };
}

int costsSeedsFor(int size, int requested) {
  if (requested > 0) return requested;
  return size <= 400 ? 20 : 10;
}

std::vector<CostVariant> costVariants() {
  return {
      {VariantKey::kAStar, "A*", eaci::Algorithm::kAStar, false},
      {VariantKey::kAStarSmoothed, "A*, smoothed", eaci::Algorithm::kAStar, true},
      {VariantKey::kEaci1t, "EACI", eaci::Algorithm::kEaci, false},
      {VariantKey::kEaciSmoothed1t, "EACI, smoothed", eaci::Algorithm::kEaci, true},
  };
}

int runCostsCommand(CostsOptions options) {
  if (options.quick) {
    options.sizes = {100, 200};
    if (options.runs == 0) options.runs = 2;
    options.lab_seeds = std::min(options.lab_seeds, 2);
  }
  const Provenance provenance = collectProvenance(options.command_line);
  CostsRunner runner(options);
  const std::vector<CostGroup> groups = runner.run();
  writeReport(options.out_dir, "costs",
              {costsJson(groups, options, provenance), costsCsv(groups), costsMarkdown(groups, options, provenance), {}});
  return 0;
}

}  // namespace eaci_bench
