// `eaci_bench paper`: the paper's Tables 1-3 on its maps, corner cutting allowed, the
// paper's comparison parameters, seeds 1..runs: classic ACO, EACI with the paper's islands,
// EACI with geodesic islands, and the exact A* length.
#pragma once

#include <string>
#include <vector>

#include "eaci/io/occupancy_map.hpp"
#include "eaci/planner.hpp"
#include "paper_maps.hpp"
#include "plan_runner.hpp"
#include "run_record.hpp"
#include "statistics.hpp"
#include "variant_key.hpp"

namespace eaci_bench {

struct PaperOptions {
  std::string maps_dir;
  int runs = 20;
  std::string out_dir = "out/bench";
  int threads = 1;
  std::vector<int> snapshot_iterations = {0, 1, 5, 15, 30};
  std::string command_line;
};

// One algorithm as the paper benchmark runs it.
struct Variant {
  VariantKey key = VariantKey::kAco;
  std::string label;            // for tables and plots
  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;
  std::string island_strategy;  // "" for ACO
  std::vector<std::pair<std::string, std::string>> settings;  // further parameters (setParameter)
};

const std::vector<Variant>& paperVariants();
const Variant& paperVariant(VariantKey key);  // throws std::invalid_argument

struct VariantResult {
  Variant variant;
  std::vector<RunRecord> runs;
  Summary summary;
  std::vector<PheromoneSnapshot> snapshots;  // EACI, seed 1
};

struct MapResult : LoadedPaperMap {
  RunRecord astar;
  std::vector<VariantResult> variants;
};

// The paper's comparison parameters (the Parameters defaults) with corner cutting allowed,
// then the variant's own settings.
eaci::Parameters paperParameters(const Variant& variant, std::uint64_t seed, int threads);

// A plan on a paper map, and the exact A* reference (corner cutting allowed; time: median of 21).
PlanRequest paperRequest(const LoadedPaperMap& m, eaci::Algorithm algorithm, const eaci::Parameters& params);
RunRecord paperAStar(const LoadedPaperMap& m);

// Runs everything and writes paper.json, paper.csv, paper_runs.csv and paper.md into out_dir.
// Returns the process exit status.
int runPaperCommand(const PaperOptions& options);

}  // namespace eaci_bench
