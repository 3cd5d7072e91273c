#include "scale.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "forked_run.hpp"
#include "plan_runner.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report_format.hpp"
#include "scale_report.hpp"

namespace eaci_bench {

namespace {

std::string seconds(double ms) { return fixed(ms / 1000.0, 1) + " s"; }

eaci::Parameters scaleParameters(const ScaleVariant& v, std::uint64_t seed) {
  eaci::Parameters params;  // defaults: geodesic islands, corner cutting forbidden
  params.seed = seed;
  params.threads = v.threads;
  params.early_stop_iterations = v.early_stop_iterations;
  return params;
}

// One plan in its own child process.
ScaleRun runOne(const GeneratedMap& g, const ScaleVariant& v, std::uint64_t seed, double budget_ms, bool keep_path) {
  const PlanRequest request{g.map.view(), g.start, g.goal, v.algorithm, scaleParameters(v, seed),
                            v.algorithm == eaci::Algorithm::kAStar ? 0.0 : budget_ms};
  const ForkedResult child = runForked([&] { return toJson(timedPlan(request), false, keep_path).dump(); });
  if (!child.ok) throw std::runtime_error(std::string(toString(v.key)) + " on " + toString(g.kind) + " " + std::to_string(g.size) + ": " +
                                          child.error);
  ScaleRun run;
  run.record = runRecordFromJson(nlohmann::json::parse(child.output));
  run.optimum = g.optimum;
  run.gap_pct = run.record.success ? (run.record.length / g.optimum - 1.0) * 100.0
                                   : std::numeric_limits<double>::infinity();
  run.peak_rss_mb = child.peak_rss_mb;
  run.plan_rss_mb = std::max(0.0, child.peak_rss_mb - child.start_rss_mb);
  return run;
}

void summarizeVariant(ScaleVariantResult& v) {
  std::vector<RunRecord> records;
  std::vector<double> gaps;  // successful runs only; success counts failures
  for (const ScaleRun& run : v.runs) {
    records.push_back(run.record);
    if (run.record.success) gaps.push_back(run.gap_pct);
    v.max_peak_rss_mb = std::max(v.max_peak_rss_mb, run.peak_rss_mb);
    v.max_plan_rss_mb = std::max(v.max_plan_rss_mb, run.plan_rss_mb);
  }
  v.summary = summarize(records, std::numeric_limits<double>::infinity());
  v.avg_gap_pct = mean(gaps);
  v.max_gap_pct = gaps.empty() ? std::numeric_limits<double>::infinity() : *std::max_element(gaps.begin(), gaps.end());
}

class ScaleRunner {
 public:
  explicit ScaleRunner(const ScaleOptions& options) : options_(options), progress_("scale") {}

  std::vector<ScaleCase> run() {
    std::vector<ScaleCase> cases;
    for (MapKind kind : options_.kinds)
      for (int size : options_.sizes) cases.push_back(runCase(kind, size));
    progress_.finish();
    return cases;
  }

 private:
  ScaleCase runCase(MapKind kind, int size) {
    ScaleCase c;
    c.size = size;
    c.kind = kind;
    const std::vector<ScaleVariant> variants = scaleVariants(options_.early_stop_iterations);
    for (const ScaleVariant& v : variants) c.variants.push_back(ScaleVariantResult{v, {}, {}, 0, 0, 0, 0, 0});
    std::set<VariantKey> skip;
    for (const ScaleVariant& v : variants)
      if (given_up_.count(givenUpKey(kind, v))) {
        skip.insert(v.key);
        addNote(c, v.label + " skipped: " + given_up_[givenUpKey(kind, v)]);
      }
    const int seeds = seedsFor(size, options_.runs);
    for (int k = 1; k <= seeds; ++k) {
      GeneratedMap g = generateMap(kind, size, static_cast<std::uint64_t>(k));
      const bool example = k == 1 && size <= options_.example_max_size;
      for (std::size_t i = 0; i < variants.size(); ++i) {
        const ScaleVariant& v = variants[i];
        if (skip.count(v.key)) {
          ++c.variants[i].skipped_seeds;
          continue;
        }
        progress_.show(std::string(toString(kind)) + " " + std::to_string(size) + " | " + toString(v.key), k, seeds);
        c.variants[i].runs.push_back(runOne(g, v, static_cast<std::uint64_t>(k), options_.budget_s * 1000.0, example));
        checkSlow(c, v, c.variants[i].runs.back().record, k, seeds, skip);
      }
      if (!example) g.map.cells.clear();
      c.maps.push_back(std::move(g));
    }
    for (ScaleVariantResult& v : c.variants) summarizeVariant(v);
    return c;
  }

  // A run stopped by the budget: this variant is dropped for the rest of this case and for
  // larger maps of the same kind. A slow run: the rest of this case's seeds are dropped.
  void checkSlow(ScaleCase& c, const ScaleVariant& v, const RunRecord& r, int k, int seeds,
                 std::set<VariantKey>& skip) {
    if (r.interrupted) {
      std::ostringstream why;
      why << "a run on " << toString(c.kind) << " " << c.size << " (seed " << k << ") hit the "
          << options_.budget_s << " s budget after " << r.iterations_run << " iterations";
      given_up_[givenUpKey(c.kind, v)] = why.str();
      skip.insert(v.key);
      addNote(c, v.label + ": " + why.str() + (k < seeds ? "; its other seeds skipped" : ""));
    } else if (r.time_ms > options_.slow_run_s * 1000.0 && k < seeds) {
      skip.insert(v.key);
      addNote(c, v.label + ": seed " + std::to_string(k) + " took " + seconds(r.time_ms) + " (over " +
                     fixed(options_.slow_run_s, 0) + " s); its other seeds skipped");
    }
  }

  void addNote(ScaleCase& c, const std::string& note) {
    c.notes.push_back(note);
    progress_.note(std::string(toString(c.kind)) + " " + std::to_string(c.size) + ": " + note);
  }

  static std::string givenUpKey(MapKind kind, const ScaleVariant& v) { return std::string(toString(kind)) + "/" + toString(v.key); }

  const ScaleOptions& options_;
  Progress progress_;
  std::map<std::string, std::string> given_up_;
};

}  // namespace

std::vector<ScaleVariant> scaleVariants(int early_stop_iterations) {
  const std::string early = "EACI, early stop " + std::to_string(early_stop_iterations);
  return {
      {VariantKey::kAStar, "A*", eaci::Algorithm::kAStar, 1, 0},
      {VariantKey::kEaci1t, "EACI, 1 thread", eaci::Algorithm::kEaci, 1, 0},
      {VariantKey::kEaciAll, "EACI, all cores", eaci::Algorithm::kEaci, 0, 0},
      {VariantKey::kEaciEarly1t, early + ", 1 thread", eaci::Algorithm::kEaci, 1, early_stop_iterations},
      {VariantKey::kEaciEarlyAll, early + ", all cores", eaci::Algorithm::kEaci, 0, early_stop_iterations},
      {VariantKey::kAco1t, "classic ACO, 1 thread", eaci::Algorithm::kAco, 1, 0},
      {VariantKey::kAcoAll, "classic ACO, all cores", eaci::Algorithm::kAco, 0, 0},
  };
}

int seedsFor(int size, int requested) {
  if (requested > 0) return requested;
  return size <= 400 ? 5 : 3;
}

int runScaleCommand(const ScaleOptions& options) {
  const Provenance provenance = collectProvenance(options.command_line);
  ScaleRunner runner(options);
  const std::vector<ScaleCase> cases = runner.run();

  writeReport(options.out_dir, "scale",
              {scaleJson(cases, options, provenance), scaleCsv(cases), scaleMarkdown(cases, options, provenance), {}});
  return 0;
}

}  // namespace eaci_bench
