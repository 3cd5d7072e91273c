// `paper` and `sweep`: the paper's maps, corner cutting allowed, the paper's comparison
// parameters (the Parameters defaults), seeds 1..runs.
#include <algorithm>

#include "common/paper_maps.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/io/text.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "studies.hpp"

namespace eaci_bench {

namespace {

using Settings = std::vector<std::pair<std::string, std::string>>;

struct Variant {
  std::string key;  // the records' "variant"
  eaci::Algorithm algorithm;
  Settings settings;
};

// Classic ACO with our defaults tau0 = 800, rho = 0.1 (weak deposits, as the common MATLAB ACO
// code's tau0 = 8 with Q = 1; `sweep` shows why), with strong deposits for contrast, EACI
// with the paper's islands and with geodesic islands, and MAACO (re-implemented from public
// descriptions, not the authors' code) with this project's decisions, then with the other
// public reading of each open choice that can move a column, one at a time ("maaco-alt ...";
// docs/algorithm.md, MAACO).
const std::vector<Variant> kPaperVariants = {
    {"aco", eaci::Algorithm::kAco, {}},
    {"aco-strong", eaci::Algorithm::kAco, {{"aco_tau0", "1"}, {"aco_rho", "0.3"}}},
    {"eaci-paper", eaci::Algorithm::kEaci, {{"island_strategy", "paper"}}},
    {"eaci-geodesic", eaci::Algorithm::kEaci, {{"island_strategy", "geodesic"}}},
    {"maaco", eaci::Algorithm::kMaaco, {}},
    {"maaco-alt maaco_candidates=nearest3", eaci::Algorithm::kMaaco, {{"maaco_candidates", "nearest3"}}},
    {"maaco-alt maaco_start_distance=straight", eaci::Algorithm::kMaaco, {{"maaco_start_distance", "straight"}}},
    {"maaco-alt maaco_bounds=tight", eaci::Algorithm::kMaaco, {{"maaco_bounds", "tight"}}},
    {"maaco-alt maaco_rho=0.1", eaci::Algorithm::kMaaco, {{"maaco_rho", "0.1"}}},
    {"maaco-alt maaco_tau0=0.1", eaci::Algorithm::kMaaco, {{"maaco_tau0", "0.1"}}},
    {"maaco-alt maaco_k_h=0.9", eaci::Algorithm::kMaaco, {{"maaco_k_h", "0.9"}}},
};

struct SweepAxis {
  std::string key;  // a Parameters name
  std::vector<double> values;
};

// The paper's Figs 11-14 (tuning runs with N = 6).
const std::vector<SweepAxis>& sweepAxes() {
  static const std::vector<SweepAxis> axes = {
      {"epsilon", {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1}},
      {"lambda", {1, 2, 3, 4, 5, 6, 10, 20, 50, 100}},
      {"islands", {2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}},
      {"kappa", {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1, 1.1, 1.2, 1.3}},
  };
  return axes;
}

// tau0 matters as tau0 * L / Q, the initial pheromone against one ant's deposit.
const std::vector<double> kAcoTau0 = {1, 100, 800, 8000};
const std::vector<double> kAcoRho = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9};


struct LoadedMap {
  eaci::paper::PaperMap spec;
  eaci::OccupancyMap map;
};

std::vector<LoadedMap> loadMaps(const std::string& maps_dir, const std::vector<std::string>& only = {}) {
  std::vector<LoadedMap> maps;
  for (const eaci::paper::PaperMap& spec : eaci::paper::loadPaperMaps(maps_dir)) {
    if (!only.empty() && std::find(only.begin(), only.end(), spec.name) == only.end()) continue;
    maps.push_back({spec, eaci::loadMatrixText(maps_dir + "/" + spec.file())});
  }
  return maps;
}

eaci::Parameters parameters(const Settings& settings, std::uint64_t seed, int threads) {
  eaci::Parameters params;
  eaci::setParameter(params, "allow_corner_cutting", "true");
  for (const auto& [key, value] : settings) eaci::setParameter(params, key, value);
  params.seed = seed;
  params.threads = threads;
  return params;
}

class PaperRunner {
 public:
  PaperRunner(const PaperOptions& options, RecordWriter& out, const char* command)
      : options_(options), out_(out), progress_(command) {}

  TimedPlanRequest request(const LoadedMap& m, eaci::Algorithm algorithm, const eaci::Parameters& params) const {
    return TimedPlanRequest{m.map.view(), m.spec.start, m.spec.goal, algorithm, params, 0.0};
  }

  // The exact A* route (microseconds: the median time of 21).
  void astar(const LoadedMap& m) {
    const eaci::Parameters params = parameters({}, 1, 1);
    append(m, "astar", params, timedPlanMedian(request(m, eaci::Algorithm::kAStar, params), 21, true), {});
  }

  // Seeds 1..runs of one variant; `extra` goes into every record, pheromone snapshots into seed 1's.
  void runs(const LoadedMap& m, const std::string& variant, eaci::Algorithm algorithm, const Settings& settings,
            const nlohmann::json& extra, bool detailed, const std::string& stage) {
    for (int k = 1; k <= options_.runs; ++k) {
      progress_.show(m.spec.name + " | " + stage, k, options_.runs);
      const eaci::Parameters params = parameters(settings, static_cast<std::uint64_t>(k), options_.threads);
      nlohmann::json more = extra;
      if (detailed && k == 1 && algorithm == eaci::Algorithm::kEaci)
        more["pheromone_snapshots"] = pheromoneSnapshots(request(m, algorithm, params), options_.snapshot_iterations);
      append(m, variant, params, timedPlan(request(m, algorithm, params), detailed, detailed), more);
    }
  }

  void finish() { progress_.finish(); }

 private:
  void append(const LoadedMap& m, const std::string& variant, const eaci::Parameters& params, nlohmann::json run,
              const nlohmann::json& extra) {
    Record r;
    r.map = m.spec.name;
    r.variant = variant;
    r.problem = {{"start", m.spec.start}, {"goal", m.spec.goal}, {"width", m.map.width}, {"height", m.map.height}};
    r.params = params;
    r.run = std::move(run);
    r.extra = extra.is_null() ? nlohmann::json::object() : extra;
    out_.append(r);
  }

  const PaperOptions& options_;
  RecordWriter& out_;
  Progress progress_;
};

}  // namespace

void runPaper(const PaperOptions& options, RecordWriter& out) {
  PaperRunner runner(options, out, "paper");
  for (const LoadedMap& m : loadMaps(options.maps_dir)) {
    runner.astar(m);
    for (const Variant& v : kPaperVariants) runner.runs(m, v.key, v.algorithm, v.settings, {}, true, v.key);
  }
  runner.finish();
}

void runSweep(const PaperOptions& options, RecordWriter& out) {
  PaperRunner runner(options, out, "sweep");
  for (const LoadedMap& m : loadMaps(options.maps_dir, {"paper-20x20", "paper-40x40"})) {
    runner.astar(m);
    for (const SweepAxis& axis : sweepAxes())
      for (double value : axis.values)
        for (const std::string strategy : {"paper", "geodesic"}) {
          const Settings settings = {{"islands", "6"}, {"island_strategy", strategy}, {axis.key, eaci::formatNumber(value, 6)}};
          runner.runs(m, "eaci-" + strategy, eaci::Algorithm::kEaci, settings, {{"axis", axis.key}, {"value", value}},
                      false, strategy + " | " + axis.key + " = " + eaci::formatNumber(value, 6));
        }
  }
  for (const LoadedMap& m : loadMaps(options.maps_dir)) {
    if (!m.spec.has_paper_rows) continue;
    runner.astar(m);
    for (double tau0 : kAcoTau0)
      for (double rho : kAcoRho)
        runner.runs(m, "aco", eaci::Algorithm::kAco, {{"aco_rho", eaci::formatNumber(rho, 6)}, {"aco_tau0", eaci::formatNumber(tau0, 6)}},
                    {{"axis", "aco"}, {"aco_rho", rho}, {"aco_tau0", tau0}}, false,
                    "aco | tau0 = " + eaci::formatNumber(tau0, 6) + ", rho = " + eaci::formatNumber(rho, 6));
  }
  runner.finish();
}

}  // namespace eaci_bench
