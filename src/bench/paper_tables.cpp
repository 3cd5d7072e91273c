#include "paper_tables.hpp"

#include <iostream>
#include <stdexcept>

#include "paper_report.hpp"
#include "parameter_symbols.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report_format.hpp"

namespace eaci_bench {

namespace {

// Strong deposits (tau0 = 1, rho = 0.3, our defaults before 2026-11-22): the contrast. Its
// label names the settings.
Variant strongAco() {
  Variant v{VariantKey::kAcoStrong, "", eaci::Algorithm::kAco, "", {{"aco_tau0", "1"}, {"aco_rho", "0.3"}}};
  v.label = "classic ACO, " + symbolValues(paperParameters(v, 1, 1), {"aco_tau0", "aco_rho"});
  return v;
}

VariantResult runVariant(const MapResult& m, const Variant& variant, const PaperOptions& options,
                         Progress& progress) {
  VariantResult result;
  result.variant = variant;
  const std::string stage = m.spec.name + " | " + toString(variant.key);
  for (int k = 1; k <= options.runs; ++k) {
    progress.show(stage, k, options.runs);
    const eaci::Parameters params = paperParameters(variant, static_cast<std::uint64_t>(k), options.threads);
    result.runs.push_back(timedPlan(paperRequest(m, variant.algorithm, params)));
  }
  result.summary = summarize(result.runs, m.astar.length);
  if (variant.algorithm == eaci::Algorithm::kEaci)
    result.snapshots =
        pheromoneSnapshots(paperRequest(m, variant.algorithm, paperParameters(variant, 1, options.threads)),
                           options.snapshot_iterations);
  return result;
}

}  // namespace

PlanRequest paperRequest(const LoadedPaperMap& m, eaci::Algorithm algorithm, const eaci::Parameters& params) {
  return PlanRequest{m.map.view(), m.start, m.goal, algorithm, params, 0.0};
}

RunRecord paperAStar(const LoadedPaperMap& m) {
  constexpr int kRepeats = 21;  // A* takes microseconds here: report the median of several timings
  eaci::Parameters params;
  eaci::setParameter(params, "allow_corner_cutting", "true");
  RunRecord record = timedPlan(paperRequest(m, eaci::Algorithm::kAStar, params));
  std::vector<double> times = {record.time_ms}, cpu_times = {record.cpu_ms};
  for (int k = 1; k < kRepeats; ++k) {
    const RunRecord again = timedPlan(paperRequest(m, eaci::Algorithm::kAStar, params));
    times.push_back(again.time_ms);
    cpu_times.push_back(again.cpu_ms);
  }
  record.time_ms = record.time_to_best_ms = median(times);
  record.cpu_ms = median(cpu_times);
  return record;
}

const std::vector<Variant>& paperVariants() {
  static const std::vector<Variant> variants = {
      // Our defaults tau0 = 800, rho = 0.1: weak deposits against the initial pheromone, like the
      // common MATLAB ACO code (tau0 = 8, Q = 1); `eaci_bench sweep` shows why.
      {VariantKey::kAco, "classic ACO", eaci::Algorithm::kAco, "", {}},
      strongAco(),
      {VariantKey::kEaciPaper, "EACI, paper islands", eaci::Algorithm::kEaci, "paper", {}},
      {VariantKey::kEaciGeodesic, "EACI, geodesic islands", eaci::Algorithm::kEaci, "geodesic", {}},
  };
  return variants;
}

const Variant& paperVariant(VariantKey key) {
  for (const Variant& v : paperVariants())
    if (v.key == key) return v;
  throw std::invalid_argument(std::string("no paper variant '") + toString(key) + "'");
}

eaci::Parameters paperParameters(const Variant& variant, std::uint64_t seed, int threads) {
  eaci::Parameters params;  // the defaults are the paper's comparison parameters
  eaci::setParameter(params, "allow_corner_cutting", "true");
  if (!variant.island_strategy.empty()) eaci::setParameter(params, "island_strategy", variant.island_strategy);
  for (const auto& [key, value] : variant.settings) eaci::setParameter(params, key, value);
  params.seed = seed;
  params.threads = threads;
  return params;
}

int runPaperCommand(const PaperOptions& options) {
  const Provenance provenance = collectProvenance(options.command_line);
  Progress progress("paper");
  std::vector<MapResult> results;
  for (const PaperMap& spec : paperMaps()) {
    MapResult m;
    static_cast<LoadedPaperMap&>(m) = loadPaperMap(options.maps_dir, spec);
    m.astar = paperAStar(m);
    for (const Variant& variant : paperVariants()) m.variants.push_back(runVariant(m, variant, options, progress));
    results.push_back(std::move(m));
  }
  progress.finish();

  writeReport(options.out_dir, "paper",
              {paperJson(results, options, provenance), paperSummaryCsv(results),
               paperMarkdown(results, options, provenance), {{"_runs.csv", paperRunsCsv(results)}}});
  return 0;
}

}  // namespace eaci_bench
