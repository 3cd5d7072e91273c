#include "sweeps.hpp"

#include <cmath>
#include <iostream>

#include "eaci/planner/parameters.hpp"
#include "eaci/io/text.hpp"
#include "paper_tables.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report_format.hpp"
#include "sweep_report.hpp"

namespace eaci_bench {

namespace {

std::vector<double> steps(double first, double last, double step) {
  std::vector<double> values;
  for (int k = 0;; ++k) {
    const double v = std::round((first + k * step) * 1e9) / 1e9;
    if (v > last + 1e-9) break;
    values.push_back(v);
  }
  return values;
}

// The paper's tuning parameters, EACI with `strategy` islands, the axis at `value`.
eaci::Parameters tuningParameters(const SweepAxis& axis, double value, const std::string& strategy,
                                  std::uint64_t seed, int threads) {
  eaci::Parameters params = paperTuningParameters();
  eaci::setParameter(params, "island_strategy", strategy);
  for (const auto& [key, text] : axis.base) eaci::setParameter(params, key, text);
  eaci::setParameter(params, axis.key, parameterText(value));
  params.seed = seed;
  params.threads = threads;
  return params;
}

std::vector<RunRecord> repeatedRuns(const LoadedPaperMap& m, eaci::Algorithm algorithm, int runs,
                                    const std::function<eaci::Parameters(std::uint64_t)>& parameters,
                                    const std::string& stage, Progress& progress) {
  std::vector<RunRecord> records;
  for (int k = 1; k <= runs; ++k) {
    progress.show(stage, k, runs);
    records.push_back(timedPlan(paperRequest(m, algorithm, parameters(static_cast<std::uint64_t>(k)))));
  }
  return records;
}

std::vector<SweepPoint> runEaciSweeps(const SweepOptions& options, Progress& progress) {
  std::vector<SweepPoint> points;
  for (const std::string& name : options.eaci_maps) {
    const LoadedPaperMap m = loadPaperMap(options.maps_dir, paperMapNamed(name));
    const double optimum = paperAStar(m).length;
    for (const SweepAxis& axis : eaciSweepAxes())
      for (double value : axis.values)
        for (const std::string& strategy : options.strategies) {
          SweepPoint p{axis.key, value, name, strategy, {}, {}};
          const std::string stage = name + " | " + strategy + " | " + axis.key + " = " + parameterText(value);
          p.runs = repeatedRuns(
              m, eaci::Algorithm::kEaci, options.runs,
              [&](std::uint64_t seed) { return tuningParameters(axis, value, strategy, seed, options.threads); },
              stage, progress);
          p.summary = summarize(p.runs, optimum);
          points.push_back(std::move(p));
        }
  }
  return points;
}

RhoPoint rhoPoint(const LoadedPaperMap& m, double rho, double tau0, double optimum, const SweepOptions& options,
                  Progress& progress) {
  RhoPoint p;
  p.map = m.spec.name;
  p.rho = rho;
  p.tau0 = tau0;
  p.paper = *m.spec.paper_aco;
  p.runs = repeatedRuns(
      m, eaci::Algorithm::kAco, options.runs,
      [&](std::uint64_t seed) {
        eaci::Parameters params;
        eaci::setParameter(params, "allow_corner_cutting", "true");
        eaci::setParameter(params, "aco_rho", parameterText(rho));
        eaci::setParameter(params, "aco_tau0", parameterText(tau0));
        params.seed = seed;
        params.threads = options.threads;
        return params;
      },
      m.spec.name + " | aco | tau0 = " + parameterText(tau0) + ", rho = " + parameterText(rho), progress);
  p.summary = summarize(p.runs, optimum);
  p.iterations_ratio = p.summary.avg_iterations / p.paper.avg_iterations;
  p.lost_ants_ratio = p.summary.avg_lost_ants / p.paper.avg_lost_ants;
  auto within = [](double r) { return r >= 0.5 && r <= 2.0; };
  p.within_factor_2 = within(p.iterations_ratio) && within(p.lost_ants_ratio);
  return p;
}

std::vector<RhoPoint> runRhoSweep(const SweepOptions& options, Progress& progress) {
  std::vector<RhoPoint> points;
  for (const PaperMap& spec : paperMaps()) {
    if (!spec.paper_aco) continue;
    const LoadedPaperMap m = loadPaperMap(options.maps_dir, spec);
    const double optimum = paperAStar(m).length;
    for (double tau0 : acoTau0Values())
      for (double rho : acoRhoValues()) points.push_back(rhoPoint(m, rho, tau0, optimum, options, progress));
  }
  return points;
}

}  // namespace

std::string parameterText(double value) { return eaci::formatNumber(value, 6); }

eaci::Parameters paperTuningParameters() {
  eaci::Parameters params;
  eaci::setParameter(params, "allow_corner_cutting", "true");
  eaci::setParameter(params, "islands", "6");
  return params;
}

const std::vector<SweepAxis>& eaciSweepAxes() {
  static const std::vector<SweepAxis> axes = {
      {"epsilon", "Fig. 11", steps(0.1, 1.0, 0.1), {}},
      {"lambda", "Fig. 12", {1, 2, 3, 4, 5, 6, 10, 20, 50, 100}, {}},
      {"islands", "Fig. 13", steps(2, 15, 1), {}},
      {"kappa", "Fig. 14", steps(0.1, 1.3, 0.1), {}},
  };
  return axes;
}

const std::vector<double>& acoRhoValues() {
  static const std::vector<double> values = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9};
  return values;
}

const std::vector<double>& acoTau0Values() {
  static const std::vector<double> values = {1, 100, 800, 8000};
  return values;
}

int runSweepCommand(const SweepOptions& options) {
  const Provenance provenance = collectProvenance(options.command_line);
  Progress progress("sweep");
  const std::vector<SweepPoint> eaci_points = runEaciSweeps(options, progress);
  const std::vector<RhoPoint> rho_points = runRhoSweep(options, progress);
  progress.finish();

  writeReport(options.out_dir, "sweep",
              {sweepJson(eaci_points, rho_points, options, provenance), sweepCsv(eaci_points, rho_points),
               sweepMarkdown(eaci_points, rho_points, options, provenance), {}});
  return 0;
}

}  // namespace eaci_bench
