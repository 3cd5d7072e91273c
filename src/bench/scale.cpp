// `scale` and `deadline`: generated maps (map_generator.hpp), the robot's move rule, default
// parameters (geodesic EACI); every plan in its own child process (forked_run.hpp) for its peak memory.
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "forked_run.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "studies.hpp"

namespace eaci_bench {

namespace {

struct ScaleVariant {
  std::string key;
  eaci::Algorithm algorithm;
  int threads;  // 0 = all cores
  bool early_stop;
};

const std::vector<ScaleVariant> kScaleVariants = {
    {"astar", eaci::Algorithm::kAStar, 1, false},        {"eaci-1t", eaci::Algorithm::kEaci, 1, false},
    {"eaci-all", eaci::Algorithm::kEaci, 0, false},      {"eaci-early-1t", eaci::Algorithm::kEaci, 1, true},
    {"eaci-early-all", eaci::Algorithm::kEaci, 0, true}, {"aco-1t", eaci::Algorithm::kAco, 1, false},
    {"aco-all", eaci::Algorithm::kAco, 0, false},
};

nlohmann::json problemOf(const GeneratedMap& g, bool with_grid) {
  nlohmann::json p = {{"kind", toString(g.kind)}, {"size", g.size}, {"map_seed", g.seed}, {"map_seed_used", g.seed_used},
                      {"start", g.start}, {"goal", g.goal}, {"obstacle_fraction", g.obstacle_fraction},
                      {"optimum", g.optimum}};
  if (with_grid) p["grid"] = g.map.cells;  // row-major, first row on top, 0 free / 100 obstacle
  return p;
}

// One plan in a child process: its record and the child's peak memory.
Record forkedPlan(const GeneratedMap& g, const std::string& variant, const TimedPlanRequest& request, bool keep_path) {
  const ForkedResult child = runForked([&] { return timedPlan(request, false, keep_path).dump(); });
  if (!child.ok) throw std::runtime_error(variant + " on " + toString(g.kind) + " " + std::to_string(g.size) + ": " + child.error);
  Record r;
  r.map = std::string(toString(g.kind)) + " " + std::to_string(g.size);
  r.variant = variant;
  r.problem = problemOf(g, keep_path);
  r.params = request.params;
  r.run = nlohmann::json::parse(child.output);
  r.extra = {{"peak_rss_mb", child.peak_rss_mb}, {"plan_rss_mb", std::max(0.0, child.peak_rss_mb - child.start_rss_mb)}};
  return r;
}

}  // namespace

void runScale(const GeneratedOptions& o, RecordWriter& out) {
  Progress progress("scale");
  std::map<std::string, std::string> given_up;  // kind/variant -> why: a run hit the budget, larger maps skip it
  for (MapKind kind : o.kinds)
    for (int size : o.sizes) {
      const std::string name = std::string(toString(kind)) + " " + std::to_string(size);
      const int seeds = o.runs > 0 ? o.runs : size <= 400 ? 5 : 3;
      std::set<std::string> skip;  // variants dropped for the rest of this case
      for (const ScaleVariant& v : kScaleVariants)
        if (given_up.count(std::string(toString(kind)) + "/" + v.key)) skip.insert(v.key);
      for (int k = 1; k <= seeds; ++k) {
        const GeneratedMap g = generateMap(kind, size, static_cast<std::uint64_t>(k));
        const bool example = k == 1 && size <= o.example_max_size;
        for (const ScaleVariant& v : kScaleVariants) {
          if (skip.count(v.key)) continue;
          progress.show(name + " | " + v.key, k, seeds);
          eaci::Parameters params;  // defaults: geodesic islands, corner cutting forbidden
          params.seed = static_cast<std::uint64_t>(k);
          params.threads = v.threads;
          params.early_stop_iterations = v.early_stop ? o.early_stop_iterations : 0;
          const double budget_ms = v.algorithm == eaci::Algorithm::kAStar ? 0.0 : o.budget_s * 1000.0;
          Record r = forkedPlan(g, v.key, TimedPlanRequest{g.map.view(), g.start, g.goal, v.algorithm, params, budget_ms}, example);
          // A run stopped by the budget: dropped for the rest of this case and larger maps of the
          // kind. A slow run: the rest of this case's seeds are dropped.
          if (r.run["interrupted"].get<bool>()) {
            given_up[std::string(toString(kind)) + "/" + v.key] = name;
            skip.insert(v.key);
            r.extra["note"] = "hit the " + std::to_string(o.budget_s) + " s budget; later seeds and larger maps skipped";
          } else if (r.run["time_ms"].get<double>() > o.slow_run_s * 1000.0 && k < seeds) {
            skip.insert(v.key);
            r.extra["note"] = "slower than " + std::to_string(o.slow_run_s) + " s; later seeds skipped";
          }
          if (r.extra.contains("note")) progress.note(name + " | " + v.key + ": " + r.extra["note"].get<std::string>());
          out.append(r);
        }
      }
    }
  progress.finish();
}

void runDeadline(const GeneratedOptions& o, RecordWriter& out) {
  Progress progress("deadline");
  for (MapKind kind : o.kinds)
    for (int size : o.sizes)
      for (int k = 1; k <= std::max(o.runs, 1); ++k) {
        const GeneratedMap g = generateMap(kind, size, static_cast<std::uint64_t>(k));
        for (double limit_s : o.limits_s) {
          std::ostringstream label;
          label << toString(kind) << " " << size << " | limit " << limit_s << " s";
          progress.show(label.str(), k, std::max(o.runs, 1));
          // Iterations enough to outlast any limit, early stopping off: only the wall clock ends it.
          eaci::Parameters params;
          params.seed = g.seed;
          params.threads = o.threads;
          params.max_iterations = 1000000;
          params.early_stop_iterations = 0;
          Record r = forkedPlan(g, "eaci", TimedPlanRequest{g.map.view(), g.start, g.goal, eaci::Algorithm::kEaci, params,
                                                       limit_s * 1000.0}, false);
          r.problem["limit_s"] = limit_s;
          out.append(r);
        }
      }
  progress.finish();
}

}  // namespace eaci_bench
