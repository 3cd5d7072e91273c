#include "sweep_report.hpp"

#include <algorithm>
#include <sstream>

#include "eaci/planner/parameters.hpp"
#include "paper_maps.hpp"
#include "parameter_symbols.hpp"
#include "report_format.hpp"
#include "variant_key.hpp"

namespace eaci_bench {

namespace {

nlohmann::json compactRuns(const std::vector<RunRecord>& runs) {
  nlohmann::json out = nlohmann::json::array();
  for (const RunRecord& r : runs) out.push_back(toJson(r, false, false));
  return out;
}

const SweepPoint* findPoint(const std::vector<SweepPoint>& points, const std::string& axis, double value,
                            const std::string& map, const std::string& strategy) {
  for (const SweepPoint& p : points)
    if (p.axis == axis && p.value == value && p.map == map && p.strategy == strategy) return &p;
  return nullptr;
}

std::string optimalText(const Summary& s) { return std::to_string(s.optimal_runs) + "/" + std::to_string(s.runs); }

std::string axisTable(const std::vector<SweepPoint>& points, const SweepAxis& axis, const std::string& map,
                      const std::vector<std::string>& strategies) {
  std::vector<std::string> header = {paperSymbol(axis.key)};
  for (const std::string& strategy : strategies)
    for (const char* column : {"length", "iterations", "lost ants", "optimal"})
      header.push_back(strategy + ": " + column);
  MarkdownTable table(header);
  for (double value : axis.values) {
    std::vector<std::string> row = {parameterText(value)};
    for (const std::string& strategy : strategies) {
      const SweepPoint* p = findPoint(points, axis.key, value, map, strategy);
      if (p == nullptr) {
        row.insert(row.end(), {"", "", "", ""});
        continue;
      }
      row.insert(row.end(), {fixed(p->summary.avg_length, 3), fixed(p->summary.avg_iterations, 2),
                             fixed(p->summary.avg_lost_ants, 1), optimalText(p->summary)});
    }
    table.addRow(row);
  }
  return table.render();
}

std::vector<const RhoPoint*> withTau0(const std::vector<RhoPoint>& rho, double tau0) {
  std::vector<const RhoPoint*> out;
  for (const RhoPoint& p : rho)
    if (p.tau0 == tau0) out.push_back(&p);
  return out;
}

// Every number of the points with one tau0.
std::string rhoDetailTable(const std::vector<const RhoPoint*>& points) {
  MarkdownTable table({"map", "ρ", "iterations", "paper", "ours ÷ paper", "lost ants", "paper", "ours ÷ paper",
                       "avg length", "best length", "success", "within 2× on both"});
  for (const RhoPoint* p : points)
    table.addRow({p->map, parameterText(p->rho), fixed(p->summary.avg_iterations, 2), fixed(p->paper.avg_iterations, 1),
                  ratio(p->summary.avg_iterations, p->paper.avg_iterations), fixed(p->summary.avg_lost_ants, 1),
                  fixed(p->paper.avg_lost_ants, 1), ratio(p->summary.avg_lost_ants, p->paper.avg_lost_ants),
                  fixed(p->summary.avg_length, 3), fixed(p->summary.best_length, 3),
                  std::to_string(p->summary.successes) + "/" + std::to_string(p->summary.runs),
                  p->within_factor_2 ? "yes" : "no"});
  return table.render();
}

std::vector<std::string> rhoMaps(const std::vector<RhoPoint>& rho) {
  std::vector<std::string> maps;
  for (const RhoPoint& p : rho)
    if (std::find(maps.begin(), maps.end(), p.map) == maps.end()) maps.push_back(p.map);
  return maps;
}

// One tau0: rows rho, per map "iterations (ratio) / lost ants (ratio)".
std::string rhoGridTable(const std::vector<RhoPoint>& rho, double tau0) {
  const std::vector<std::string> maps = rhoMaps(rho);
  std::vector<std::string> header = {"ρ"};
  for (const std::string& map : maps) header.push_back(map + ": iterations / lost ants");
  header.push_back("all maps within 2×");
  MarkdownTable table(header);
  for (double value : acoRhoValues()) {
    std::vector<std::string> row = {parameterText(value)};
    bool all = true;
    for (const std::string& map : maps) {
      const RhoPoint* found = nullptr;
      for (const RhoPoint& p : rho)
        if (p.tau0 == tau0 && p.rho == value && p.map == map) found = &p;
      if (found == nullptr) {
        row.push_back("");
        all = false;
        continue;
      }
      all = all && found->within_factor_2;
      row.push_back(fixed(found->summary.avg_iterations, 1) + " (" + ratio(found->summary.avg_iterations, found->paper.avg_iterations) +
                    ") / " + fixed(found->summary.avg_lost_ants, 0) + " (" +
                    ratio(found->summary.avg_lost_ants, found->paper.avg_lost_ants) + ")");
    }
    row.push_back(all ? "**yes**" : "no");
    table.addRow(row);
  }
  return table.render();
}

// (tau0, rho) pairs within a factor 2 of the paper's ACO iterations and lost ants on every map.
std::vector<std::pair<double, double>> passingSettings(const std::vector<RhoPoint>& rho) {
  std::vector<std::pair<double, double>> passing;
  for (double tau0 : acoTau0Values())
    for (double value : acoRhoValues()) {
      int maps = 0;
      bool all = true;
      for (const RhoPoint& p : rho)
        if (p.tau0 == tau0 && p.rho == value) {
          ++maps;
          all = all && p.within_factor_2;
        }
      if (maps > 0 && all) passing.emplace_back(tau0, value);
    }
  return passing;
}

std::string rhoVerdict(const std::vector<RhoPoint>& rho) {
  const auto passing = passingSettings(rho);
  const eaci::Parameters defaults;
  bool defaults_pass = false;
  for (const auto& [tau0, value] : passing)
    defaults_pass = defaults_pass || (tau0 == defaults.aco_tau0 && value == defaults.aco_rho);
  std::ostringstream s;
  s << "Our defaults (τ0 = " << parameterText(defaults.aco_tau0) << ", ρ = " << parameterText(defaults.aco_rho) << ") "
    << (defaults_pass ? "bring classic ACO within a factor 2 of the paper's ACO iterations and lost ants on every map."
                      : "**do not bring classic ACO within a factor 2 of the paper's ACO iterations and lost ants on "
                        "every map.**")
    << " With τ0 = 1 (strong deposits) our ants find the goal, deposit, and stop getting lost after a few "
       "iterations."
    << "\n\nSettings within a factor 2 on every map:";
  if (passing.empty()) s << " none.";
  for (std::size_t k = 0; k < passing.size(); ++k)
    s << (k ? "," : "") << " τ0 = " << parameterText(passing[k].first) << " with ρ = " << parameterText(passing[k].second);
  s << "\n";
  return s.str();
}

}  // namespace

nlohmann::json sweepJson(const std::vector<SweepPoint>& eaci, const std::vector<RhoPoint>& rho,
                         const SweepOptions& options, const Provenance& provenance) {
  nlohmann::json axes = nlohmann::json::array();
  for (const SweepAxis& axis : eaciSweepAxes()) {
    nlohmann::json base = nlohmann::json::object();
    for (const auto& [key, text] : axis.base) base[key] = text;
    axes.push_back({{"parameter", axis.key}, {"symbol", paperSymbol(axis.key)}, {"figure", axis.figure},
                    {"values", axis.values}, {"base", base}});
  }
  nlohmann::json points = nlohmann::json::array();
  for (const SweepPoint& p : eaci)
    points.push_back({{"parameter", p.axis}, {"value", p.value}, {"map", p.map}, {"strategy", p.strategy},
                      {"summary", p.summary}, {"runs", compactRuns(p.runs)}});
  nlohmann::json rho_points = nlohmann::json::array();
  for (const RhoPoint& p : rho)
    rho_points.push_back({{"map", p.map}, {"rho", p.rho}, {"tau0", p.tau0}, {"summary", p.summary}, {"paper_aco", p.paper},
                          {"iterations_ratio", p.iterations_ratio}, {"lost_ants_ratio", p.lost_ants_ratio},
                          {"within_factor_2", p.within_factor_2}, {"runs", compactRuns(p.runs)}});
  return {{"kind", "sweep"},
          {"provenance", provenance},
          {"settings",
           {{"runs", options.runs},
            {"threads", options.threads},
            {"eaci_maps", options.eaci_maps},
            {"strategies", options.strategies},
            {"tuning_base",
             {{"islands", paperTuningParameters().islands},
              {"allow_corner_cutting", paperTuningParameters().allow_corner_cutting}}}}},
          {"eaci_axes", axes},
          {"eaci_points", points},
          {"aco_rho_values", acoRhoValues()},
          {"aco_tau0_values", acoTau0Values()},
          {"aco_rho_points", rho_points}};
}

std::string sweepCsv(const std::vector<SweepPoint>& eaci, const std::vector<RhoPoint>& rho) {
  CsvTable csv({"sweep", "parameter", "value", "aco_tau0", "map", "algorithm", "runs", "successes", "optimal_runs", "avg_length",
                "best_length", "std_length", "avg_iterations", "avg_lost_ants", "avg_time_ms", "paper_avg_iterations",
                "paper_avg_lost_ants"});
  auto common = [](const Summary& s) {
    return std::vector<std::string>{std::to_string(s.runs),       std::to_string(s.successes),
                                    std::to_string(s.optimal_runs), csvNumber(s.avg_length),
                                    csvNumber(s.best_length),     csvNumber(s.std_length),
                                    csvNumber(s.avg_iterations),  csvNumber(s.avg_lost_ants),
                                    csvNumber(s.avg_time_ms)};
  };
  for (const SweepPoint& p : eaci) {
    std::vector<std::string> row = {"eaci", p.axis, csvNumber(p.value), "", p.map, toString(eaciVariantKey(p.strategy))};
    for (const std::string& cell : common(p.summary)) row.push_back(cell);
    row.insert(row.end(), {"", ""});
    csv.addRow(row);
  }
  for (const RhoPoint& p : rho) {
    std::vector<std::string> row = {"aco_rho", "aco_rho", csvNumber(p.rho), csvNumber(p.tau0), p.map, toString(VariantKey::kAco)};
    for (const std::string& cell : common(p.summary)) row.push_back(cell);
    row.insert(row.end(), {csvNumber(p.paper.avg_iterations), csvNumber(p.paper.avg_lost_ants)});
    csv.addRow(row);
  }
  return csv.render();
}

std::string sweepMarkdown(const std::vector<SweepPoint>& eaci, const std::vector<RhoPoint>& rho,
                          const SweepOptions& options, const Provenance& provenance) {
  std::ostringstream s;
  s << "## Parameter sweeps (the paper's Figs 11–14)\n\n"
    << provenanceMarkdown(provenance) << "\n"
    << "EACI, corner cutting allowed, the paper's tuning parameters ("
    << symbolValues(paperTuningParameters(),
                    {"ants", "max_iterations", "alpha", "beta", "q", "kappa", "lambda", "epsilon", "islands"})
    << "), one parameter varied at a time, seeds 1–"
    << options.runs
    << " per value. *length*: average route length; *iterations*: average iterations to converge; "
       "*lost ants*: average lost ants per run; *optimal*: runs that returned the A* optimum.\n\n";
  for (const SweepAxis& axis : eaciSweepAxes())
    for (const std::string& map : options.eaci_maps)
      s << "### " << paperSymbol(axis.key) << " (`" << axis.key << "`, the paper's " << axis.figure << ") on " << map << "\n\n"
        << axisTable(eaci, axis, map, options.strategies) << "\n";
  s << "## Classic ACO: the evaporation rate ρ (and the initial pheromone τ0)\n\n"
    << "The paper gives no ρ and no τ0 for its ACO baseline. Classic ACO with the paper's m, Nc_max, α, β, "
    << symbolValues(eaci::Parameters{}, {"q"}) << ", corner cutting allowed, seeds 1–"
    << options.runs << "; *paper*: the paper's ACO row; *within 2×*: both iterations and lost ants within a "
       "factor 2 of the paper's.\n\n"
    << "### τ0 = " << parameterText(eaci::Parameters{}.aco_tau0) << " (our default; our default ρ is "
    << parameterText(eaci::Parameters{}.aco_rho) << ")\n\n"
    << rhoDetailTable(withTau0(rho, eaci::Parameters{}.aco_tau0)) << "\n"
    << "### Every τ0: average iterations (ours ÷ paper) / average lost ants (ours ÷ paper)\n\n"
    << "Only τ0 relative to Q / L matters (the roulette wheel of Eq. 8 does not change when every τ is "
       "scaled): τ0 = 800 with Q = 100 equals the common MATLAB ACO code's τ0 = 8 with Q = 1.\n\n";
  for (double tau0 : acoTau0Values()) s << "τ0 = " << parameterText(tau0) << ":\n\n" << rhoGridTable(rho, tau0) << "\n";
  s << rhoVerdict(rho);
  return s.str();
}

}  // namespace eaci_bench
