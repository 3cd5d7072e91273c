#include "paper_report.hpp"

#include <cmath>
#include <sstream>

#include "common/parameters_json.hpp"
#include "grid_rows.hpp"
#include "parameter_symbols.hpp"
#include "report_format.hpp"

namespace eaci_bench {

namespace {

nlohmann::json snapshotsJson(const std::vector<PheromoneSnapshot>& snapshots) {
  nlohmann::json out = nlohmann::json::array();
  for (const PheromoneSnapshot& s : snapshots) out.push_back({{"iteration", s.iteration}, {"strongest", s.strongest}});
  return out;
}

nlohmann::json variantJson(const VariantResult& v) {
  nlohmann::json runs = nlohmann::json::array();
  for (const RunRecord& run : v.runs) runs.push_back(toJson(run, true, true));
  nlohmann::json settings = nlohmann::json::object();
  for (const auto& [key, value] : v.variant.settings) settings[key] = value;
  return {{"key", toString(v.variant.key)},
          {"label", v.variant.label},
          {"island_strategy", v.variant.island_strategy},
          {"settings", settings},
          {"summary", v.summary},
          {"runs", runs},
          {"pheromone_snapshots_seed", 1},
          {"pheromone_snapshots", snapshotsJson(v.snapshots)}};
}

nlohmann::json optionalRow(const std::optional<PaperRow>& row) { return row ? nlohmann::json(*row) : nlohmann::json(nullptr); }

nlohmann::json mapJson(const MapResult& m) {
  nlohmann::json variants = nlohmann::json::array();
  for (const VariantResult& v : m.variants) variants.push_back(variantJson(v));
  return {{"name", m.spec.name},
          {"file", m.spec.file},
          {"table", m.spec.table},
          {"source", m.spec.note},
          {"width", m.map.width},
          {"height", m.map.height},
          {"start", m.start},
          {"goal", m.goal},
          {"start_serial", m.spec.start_serial},
          {"goal_serial", m.spec.goal_serial},
          {"grid", gridRows(m.map)},
          {toString(VariantKey::kAStar), toJson(m.astar, false, true)},
          {"paper", {{"aco", optionalRow(m.spec.paper_aco)}, {"eaci", optionalRow(m.spec.paper_eaci)}}},
          {"algorithms", variants}};
}

const std::optional<PaperRow>& paperRowFor(const MapResult& m, const Variant& v) {
  return v.algorithm == eaci::Algorithm::kAco ? m.spec.paper_aco : m.spec.paper_eaci;
}

std::string paperRowLabel(const Variant& v) { return v.algorithm == eaci::Algorithm::kAco ? "ACO" : "EACI"; }

// ---------------------------------------------------------------- Markdown

// The parameters of a paper variant (seed and threads do not matter here).
eaci::Parameters variantParameters(VariantKey key) { return paperParameters(paperVariant(key), 1, 1); }

std::string settingsParagraph(const PaperOptions& options) {
  const eaci::Parameters aco = variantParameters(VariantKey::kAco);
  std::ostringstream s;
  s << "Corner cutting allowed (the paper's move rule); the paper's comparison parameters "
    << symbolValues(aco, {"ants", "max_iterations", "alpha", "beta", "q", "kappa", "lambda", "islands", "epsilon"})
    << "; classic ACO with " << symbolValues(aco, {"aco_tau0"}) << " and " << symbolValues(aco, {"aco_rho"})
    << " (our defaults; the paper gives neither: weak deposits, as in the common MATLAB ACO code's τ0 = 8 with "
       "Q = 1, chosen by `eaci_bench sweep`), and with "
    << symbolValues(variantParameters(VariantKey::kAcoStrong), {"aco_tau0", "aco_rho"})
    << " (strong deposits, for contrast); seeds 1–"
    << options.runs << "; " << options.threads
    << " thread(s) per plan. *iterations*: the iteration that first reached the run's final length "
       "(the paper's \"average iterative times\"); *lost ants*: total over the run; *std*: sample "
       "standard deviation of the route length; *angle*: total corner angle of the best run's route (the "
       "shortest; among equally short routes the one that turns least); "
       "*optimal*: runs that returned the A* optimum; *gap*: average length over the A* optimum; "
       "*ms/run*: median wall time of one `eaci::plan()` call; *ms to best*: median wall time until the end "
       "of the iteration that found the run's final route. Paper rows are the paper's tables verbatim.\n";
  return s.str();
}

std::vector<std::string> paperRowCells(const std::string& label, const PaperRow& p) {
  return {label,           fixed(p.avg_iterations, 2), fixed(p.avg_length, 2), fixed(p.best_length, 2),
          fixed(p.std_length, 4), fixed(p.avg_lost_ants, 2), fixed(p.turn_deg, 0), "", "", "", "", ""};
}

std::vector<std::string> ourRowCells(const std::string& label, const Summary& s) {
  return {label,
          fixed(s.avg_iterations, 2),
          fixed(s.avg_length, 4),
          fixed(s.best_length, 4),
          fixed(s.std_length, 4),
          fixed(s.avg_lost_ants, 2),
          fixed(s.best_route_turn_deg, 0),
          std::to_string(s.successes) + "/" + std::to_string(s.runs),
          std::to_string(s.optimal_runs) + "/" + std::to_string(s.runs),
          fixed(s.avg_gap_pct, 2) + " %",
          fixed(s.median_time_ms, 2),
          fixed(s.median_time_to_best_ms, 2)};
}

std::string mapTable(const MapResult& m) {
  MarkdownTable table({"row", "iterations", "avg length", "best length", "std", "lost ants", "angle (°)", "success",
                       "optimal", "gap", "ms/run", "ms to best"});
  table.addRow({"A* (exact)", "", fixed(m.astar.length, 4), fixed(m.astar.length, 4), "", "",
                fixed(m.astar.total_turn_deg, 0), m.astar.success ? "1/1" : "0/1", "", "0 %",
                fixed(m.astar.time_ms, 3), ""});
  std::string last_family;
  for (const VariantResult& v : m.variants) {
    const auto& paper = paperRowFor(m, v.variant);
    const std::string family = paperRowLabel(v.variant);
    if (paper && family != last_family) table.addRow(paperRowCells("paper: " + family, *paper));
    last_family = family;
    table.addRow(ourRowCells("ours: " + v.variant.label, v.summary));
  }
  std::ostringstream s;
  s << "### " << m.spec.name << " (" << m.map.width << "×" << m.map.height << ", " << m.spec.start_serial << " → "
    << m.spec.goal_serial << ")" << (m.spec.table.empty() ? "" : ", the paper's " + m.spec.table) << "\n\n"
    << "Map: " << m.spec.note << ".";
  if (m.spec.table.empty()) s << " The paper's rows are those of the 20×20 above.";
  s << "\n\n" << table.render() << "\n";
  return s.str();
}

const VariantResult* findVariant(const MapResult& m, VariantKey key) {
  for (const VariantResult& v : m.variants)
    if (v.variant.key == key) return &v;
  return nullptr;
}

std::string ratioTable(const std::vector<MapResult>& results) {
  const std::string strong = "ACO " + symbolValues(variantParameters(VariantKey::kAcoStrong), {"aco_tau0", "aco_rho"}, " ", " ");
  MarkdownTable table({"map", "ACO iterations", "ACO lost ants", strong + " iterations",
                       strong + " lost ants", "EACI-paper iterations", "EACI-paper lost ants",
                       "EACI-paper best length", "EACI-paper angle", "EACI-geodesic optimal",
                       "EACI-geodesic iterations", "EACI-geodesic lost ants"});
  for (const MapResult& m : results) {
    if (!m.spec.paper_aco || !m.spec.paper_eaci) continue;
    const PaperRow& aco = *m.spec.paper_aco;
    const PaperRow& eaci = *m.spec.paper_eaci;
    const Summary& a = findVariant(m, VariantKey::kAco)->summary;
    const Summary& w = findVariant(m, VariantKey::kAcoStrong)->summary;
    const Summary& p = findVariant(m, VariantKey::kEaciPaper)->summary;
    const Summary& g = findVariant(m, VariantKey::kEaciGeodesic)->summary;
    table.addRow({m.spec.name, ratio(a.avg_iterations, aco.avg_iterations), ratio(a.avg_lost_ants, aco.avg_lost_ants),
                  ratio(w.avg_iterations, aco.avg_iterations), ratio(w.avg_lost_ants, aco.avg_lost_ants),
                  ratio(p.avg_iterations, eaci.avg_iterations), ratio(p.avg_lost_ants, eaci.avg_lost_ants),
                  ratio(p.best_length, eaci.best_length), ratio(p.best_route_turn_deg, eaci.turn_deg),
                  std::to_string(g.optimal_runs) + "/" + std::to_string(g.runs),
                  ratio(g.avg_iterations, eaci.avg_iterations), ratio(g.avg_lost_ants, eaci.avg_lost_ants)});
  }
  return table.render();
}

// Per map and planner: wall and CPU time per run, wall time to the final route, and how
// much later than geodesic EACI that route came.
std::string timingTable(const std::vector<MapResult>& results) {
  MarkdownTable table({"map", "planner", "wall ms/run", "CPU ms/run", "wall ms to final route",
                       "to final route ÷ EACI-geodesic's"});
  for (const MapResult& m : results) {
    const Summary& g = findVariant(m, VariantKey::kEaciGeodesic)->summary;
    table.addRow({m.spec.name, "A*", fixed(m.astar.time_ms, 3), fixed(m.astar.cpu_ms, 3), fixed(m.astar.time_ms, 3),
                  ratio(m.astar.time_ms, g.median_time_to_best_ms)});
    for (const VariantResult& v : m.variants) {
      const Summary& s = v.summary;
      table.addRow({"", v.variant.label, fixed(s.median_time_ms, 2), fixed(s.median_cpu_ms, 2),
                    fixed(s.median_time_to_best_ms, 2), ratio(s.median_time_to_best_ms, g.median_time_to_best_ms)});
    }
  }
  return table.render();
}

}  // namespace

nlohmann::json paperJson(const std::vector<MapResult>& results, const PaperOptions& options,
                         const Provenance& provenance) {
  nlohmann::json maps = nlohmann::json::array();
  for (const MapResult& m : results) maps.push_back(mapJson(m));
  return {{"kind", "paper"},
          {"provenance", provenance},
          {"settings",
           {{"runs", options.runs},
            {"threads", options.threads},
            {"snapshot_iterations", options.snapshot_iterations},
            {"parameters", eaci::report::parametersToJson(paperParameters(paperVariants().front(), 1, options.threads))}}},
          {"maps", maps}};
}

std::string paperSummaryCsv(const std::vector<MapResult>& results) {
  CsvTable csv({"map", "algorithm", "runs", "successes", "success_rate", "optimal_runs", "avg_iterations",
                "avg_length", "best_length", "std_length", "avg_lost_ants", "best_route_turn_deg", "avg_time_ms",
                "median_time_ms", "avg_time_to_best_ms", "median_time_to_best_ms", "avg_gap_pct", "best_gap_pct", "astar_length",
                "paper_avg_iterations", "paper_avg_length", "paper_best_length", "paper_avg_lost_ants",
                "paper_turn_deg"});
  for (const MapResult& m : results) {
    const char* astar_success = m.astar.success ? "1" : "0";
    csv.addRow({m.spec.name, toString(VariantKey::kAStar), "1", astar_success, astar_success, "1", "0",
                csvNumber(m.astar.length), csvNumber(m.astar.length), "0", "0", csvNumber(m.astar.total_turn_deg),
                csvNumber(m.astar.time_ms), csvNumber(m.astar.time_ms), csvNumber(m.astar.time_ms),
                csvNumber(m.astar.time_ms), "0", "0",
                csvNumber(m.astar.length), "", "", "", "", ""});
    for (const VariantResult& v : m.variants) {
      const Summary& s = v.summary;
      const auto& paper = paperRowFor(m, v.variant);
      auto p = [&](double PaperRow::*field) { return paper ? csvNumber((*paper).*field) : std::string(); };
      csv.addRow({m.spec.name, toString(v.variant.key), std::to_string(s.runs), std::to_string(s.successes),
                  csvNumber(s.success_rate), std::to_string(s.optimal_runs), csvNumber(s.avg_iterations),
                  csvNumber(s.avg_length), csvNumber(s.best_length), csvNumber(s.std_length),
                  csvNumber(s.avg_lost_ants), csvNumber(s.best_route_turn_deg), csvNumber(s.avg_time_ms),
                  csvNumber(s.median_time_ms), csvNumber(s.avg_time_to_best_ms),
                  csvNumber(s.median_time_to_best_ms), csvNumber(s.avg_gap_pct),
                  csvNumber(s.best_gap_pct), csvNumber(m.astar.length), p(&PaperRow::avg_iterations),
                  p(&PaperRow::avg_length), p(&PaperRow::best_length), p(&PaperRow::avg_lost_ants),
                  p(&PaperRow::turn_deg)});
    }
  }
  return csv.render();
}

std::string paperRunsCsv(const std::vector<MapResult>& results) {
  CsvTable csv({"map", "algorithm", "seed", "success", "length", "iterations_to_converge", "iterations_run",
                "lost_ants_total", "total_turn_deg", "time_ms", "time_to_best_ms"});
  for (const MapResult& m : results)
    for (const VariantResult& v : m.variants)
      for (const RunRecord& r : v.runs)
        csv.addRow({m.spec.name, toString(v.variant.key), std::to_string(r.seed), r.success ? "1" : "0", csvNumber(r.length),
                    std::to_string(r.iterations_to_converge), std::to_string(r.iterations_run),
                    std::to_string(r.lost_ants_total), csvNumber(r.total_turn_deg), csvNumber(r.time_ms),
                    csvNumber(r.time_to_best_ms)});
  return csv.render();
}

std::string paperMarkdown(const std::vector<MapResult>& results, const PaperOptions& options,
                          const Provenance& provenance) {
  std::ostringstream s;
  s << "## Tables 1–3: our numbers beside the paper's\n\n"
    << provenanceMarkdown(provenance) << "\n"
    << settingsParagraph(options) << "\n";
  for (const MapResult& m : results) s << mapTable(m);
  s << "### Ours ÷ paper\n\nRatios of our averages to the paper's EACI and ACO rows (1.00× = equal; "
       "*optimal*: runs that returned the A* optimum).\n\n"
    << ratioTable(results) << "\n"
    << "### Time to the final route\n\n"
    << "Medians over the runs (robust to other load on the machine) of one `eaci::plan()` call on "
    << options.threads
    << " thread(s): wall time, CPU time of the process (hardly affected by other programs on the "
       "cores), and wall time until the end of the iteration that found the run's final route.\n\n"
    << timingTable(results);
  return s.str();
}

}  // namespace eaci_bench
