// `costs`: cost-aware planning on inflated cost maps (issue #10): the lab with the move_base
// config's inflation and generated rooms and clutter maps; A* and EACI, smoothed or not, one
// thread, each plan in a child process; the driven routes checked and A*'s cost set beside an
// independent weighted Dijkstra (cost_checks.hpp).
#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "cost_checks.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/number_text.hpp"
#include "eaci/search/astar.hpp"
#include "forked_run.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "studies.hpp"

namespace eaci_bench {

namespace {

struct CostVariant {
  std::string key;
  eaci::Algorithm algorithm;
  bool smooth;
};

const std::vector<CostVariant> kCostVariants = {
    {"astar", eaci::Algorithm::kAStar, false},
    {"astar-smoothed", eaci::Algorithm::kAStar, true},
    {"eaci", eaci::Algorithm::kEaci, false},
    {"eaci-smoothed", eaci::Algorithm::kEaci, true},
};

// A start and goal on the lab map, metres: the five goals of docs/ros.md's move_base runs from
// (0.4, 0.4), and three crossings.
struct LabPair {
  double start_x, start_y, goal_x, goal_y;
  const char* note;
};

const std::vector<LabPair> kLabPairs = {
    {0.4, 0.4, 4.4, 2.6, ""},           {0.4, 0.4, 2.45, 1.5, "in the U"},  {0.4, 0.4, 1.1, 2.2, "behind the L"},
    {0.4, 0.4, 4.2, 0.5, "past the cubes"}, {0.4, 0.4, 0.5, 2.6, ""},       {4.4, 2.6, 0.5, 2.6, "along the top"},
    {1.1, 2.2, 4.2, 0.5, "diagonal"},   {2.45, 1.5, 4.4, 2.6, "out of the U"},
};

// A map to plan on: its inflated costs, the grids the checks read.
struct PreparedMap {
  CostBytes costs;
  eaci::GridView view;       // over costs.bytes, read as the planners read a costmap
  eaci::CostGrid planning;   // >= 253 blocked, the rest weighted
  eaci::CostGrid obstacles;  // the map's own obstacles (clearance)
};

void prepare(PreparedMap& m, const eaci::OccupancyMap& map, const eaci::InflationParameters& inflation, double resolution) {
  const eaci::Parameters defaults;
  const eaci::UnknownPolicy unknown = defaults.allow_unknown ? eaci::UnknownPolicy::kExpensive : eaci::UnknownPolicy::kObstacle;
  m.costs = CostBytes{map.width, map.height, eaci::inflatedCosts(map.view(unknown), resolution, inflation)};
  m.view = eaci::GridView(m.costs.bytes.data(), map.width, map.height, eaci::RowOrder::kTopFirst,
                          eaci::inflatedCostsInterpretation(defaults.allow_unknown));
  m.planning = eaci::CostGrid::fromView(m.view, defaults.allow_corner_cutting, eaci::costRule(defaults));
  m.obstacles = eaci::CostGrid::fromView(map.view(unknown), defaults.allow_corner_cutting);
}

double blockedFraction(const CostBytes& costs) {
  const auto blocked = std::count_if(costs.bytes.begin(), costs.bytes.end(),
                                     [](std::uint8_t v) { return v >= eaci::kCostmapInscribed; });
  return costs.bytes.empty() ? 0.0 : static_cast<double>(blocked) / static_cast<double>(costs.bytes.size());
}

std::string metres(double x, double y) { return "(" + eaci::formatNumber(x, 2) + ", " + eaci::formatNumber(y, 2) + ")"; }

nlohmann::json finite(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

class CostsRunner {
 public:
  CostsRunner(const CostsOptions& options, RecordWriter& out) : o_(options), out_(out), progress_("costs") {}

  void lab() {
    const eaci::OccupancyMap map = eaci::loadMap(o_.lab_map);
    PreparedMap prepared;
    prepare(prepared, map, o_.lab_inflation, map.resolution);
    for (std::size_t p = 0; p < kLabPairs.size(); ++p) {
      const LabPair& pair = kLabPairs[p];
      const std::string name = metres(pair.start_x, pair.start_y) + " → " + metres(pair.goal_x, pair.goal_y) +
                               (*pair.note ? std::string(" ") + pair.note : "");
      const auto start = map.worldToCell({pair.start_x, pair.start_y});
      const auto goal = map.worldToCell({pair.goal_x, pair.goal_y});
      if (!start || !goal || !prepared.planning.isFree(*start) || !prepared.planning.isFree(*goal))
        throw std::runtime_error("lab pair " + name + ": start or goal off the map or in an inflated obstacle");
      nlohmann::json problem = {{"group", "lab"}, {"name", name}, {"size", map.width}, {"resolution", map.resolution}};
      if (p == 0) problem["costs"] = prepared.costs.bytes;  // the figure's cost map
      for (int k = 1; k <= o_.lab_seeds; ++k)
        runSeed("lab", problem, prepared, *start, *goal, static_cast<std::uint64_t>(k), k == 1, k, o_.lab_seeds);
    }
  }

  void generated(MapKind kind, int size) {
    const std::string group = std::string(toString(kind)) + " " + std::to_string(size);
    const int seeds = o_.runs > 0 ? o_.runs : size <= 400 ? 20 : 10;
    std::set<std::uint64_t> used;  // generateMap moves to the next seed when one fails: no map twice
    for (int k = 1; k <= seeds; ++k) {
      GeneratedMap g;
      PreparedMap prepared;
      bool found = false;
      std::vector<std::uint64_t> redrawn;
      for (int attempt = 0; attempt < 100 && !found; ++attempt) {
        g = generateMap(kind, size, static_cast<std::uint64_t>(k) + 10000ULL * static_cast<std::uint64_t>(attempt), o_.generator);
        if (used.count(g.seed_used)) continue;
        prepare(prepared, g.map, o_.generated_inflation, 1.0);
        found = prepared.planning.isFree(g.start) && prepared.planning.isFree(g.goal) &&
                eaci::cheapestPath(prepared.planning, g.start, g.goal).found;
        if (!found) redrawn.push_back(g.seed_used);
      }
      if (!found) throw std::runtime_error("no connected inflated " + group + " map for seed " + std::to_string(k));
      used.insert(g.seed_used);
      const bool example = k == 1 && size <= o_.example_max_size;
      nlohmann::json problem = {{"group", group}, {"name", group + " seed " + std::to_string(g.seed_used)},
                                {"kind", toString(kind)}, {"size", size}, {"resolution", 1.0},
                                {"map_seed", k}, {"map_seed_used", g.seed_used}, {"redrawn_map_seeds", redrawn},
                                {"obstacle_fraction", g.obstacle_fraction}};
      if (example) problem["costs"] = prepared.costs.bytes;
      runSeed(group, problem, prepared, g.start, g.goal, static_cast<std::uint64_t>(k), example, k, seeds);
    }
  }

  void finish() { progress_.finish(); }

 private:
  // The four planners on one problem with one seed; gaps and time ratios against this seed's A*.
  void runSeed(const std::string& group, nlohmann::json problem, const PreparedMap& prepared, eaci::Cell start,
               eaci::Cell goal, std::uint64_t seed, bool keep_paths, int k, int n) {
    problem["start"] = start;
    problem["goal"] = goal;
    problem["dijkstra_cost"] = finite(dijkstraCost(prepared.costs, start, goal));
    problem["blocked_fraction"] = blockedFraction(prepared.costs);
    std::vector<Record> records;
    for (const CostVariant& v : kCostVariants) {
      progress_.show(group + " | " + v.key, k, n);
      eaci::Parameters params;
      params.seed = seed;
      params.threads = 1;
      params.smooth_path = v.smooth;
      const TimedPlanRequest request{prepared.view, start, goal, v.algorithm, params,
                                v.algorithm == eaci::Algorithm::kAStar ? 0.0 : o_.budget_s * 1000.0};
      const ForkedResult child = runForked([&] { return timedPlan(request, false, true).dump(); });
      if (!child.ok) throw std::runtime_error(v.key + " on " + problem["name"].get<std::string>() + ": " + child.error);
      Record r;
      r.map = group;
      r.variant = v.key;
      r.params = params;
      r.run = nlohmann::json::parse(child.output);
      r.extra["peak_rss_mb"] = child.peak_rss_mb;
      if (r.run["success"].get<bool>()) {  // the route the robot would drive: the smoothed one when smoothing is on
        const RouteCheck c = checkRoute(prepared.planning, prepared.obstacles, prepared.costs, routeOf(r.run, true));
        r.extra["driven"] = {{"cost", finite(c.cost)}, {"length", finite(c.length)}, {"turn_deg", c.turn_deg},
                             {"min_clearance", finite(c.min_clearance)}, {"mean_cell_cost", finite(c.mean_cell_cost)},
                             {"lethal_cells", c.lethal_cells}, {"inscribed_cells", c.inscribed_cells}};
      }
      records.push_back(std::move(r));
    }
    const double astar_ms = records.front().run["time_ms"].get<double>();
    const double astar_cost = records.front().run["cost"].is_number() ? records.front().run["cost"].get<double>() : INFINITY;
    for (Record& r : records) {
      r.problem = problem;
      const bool success = r.run["success"].get<bool>();
      r.extra["time_ratio"] = finite(astar_ms > 0 ? r.run["time_ms"].get<double>() / astar_ms : INFINITY);
      r.extra["gap_pct"] = finite(success ? costGapPct(r.extra["driven"]["cost"].get<double>(), astar_cost) : INFINITY);
      if (r.variant.size() > 9 && r.variant.compare(r.variant.size() - 9, 9, "-smoothed") == 0)  // against its twin
        for (const Record& twin : records)
          if (twin.variant + "-smoothed" == r.variant) r.extra["same_grid_route"] = twin.run["path"] == r.run["path"];
    }
    for (Record& r : records) {  // the cells only for the figures' examples
      if (!keep_paths)
        for (const char* key : {"path", "smoothed_path", "islands"}) r.run.erase(key);
      out_.append(r);
    }
  }

  const CostsOptions& o_;
  RecordWriter& out_;
  Progress progress_;
};

}  // namespace

void runCosts(CostsOptions options, RecordWriter& out) {
  if (options.quick) {
    options.sizes = {100, 200};
    if (options.runs == 0) options.runs = 2;
    options.lab_seeds = std::min(options.lab_seeds, 2);
  }
  CostsRunner runner(options, out);
  if (!options.lab_map.empty()) runner.lab();
  for (MapKind kind : options.kinds)
    for (int size : options.sizes) runner.generated(kind, size);
  runner.finish();
}

}  // namespace eaci_bench
