#include "scale_report.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "common/json_number.hpp"
#include "common/parameters_json.hpp"
#include "grid_rows.hpp"
#include "parameter_symbols.hpp"
#include "report_format.hpp"

namespace eaci_bench {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

const ScaleVariantResult* findVariant(const ScaleCase& c, VariantKey key) {
  for (const ScaleVariantResult& v : c.variants)
    if (v.variant.key == key) return &v;
  return nullptr;
}

const ScaleRun* runWithSeed(const ScaleVariantResult* v, std::uint64_t seed) {
  if (v == nullptr) return nullptr;
  for (const ScaleRun& run : v->runs)
    if (run.record.seed == seed) return &run;
  return nullptr;
}

std::string caseName(const ScaleCase& c) { return std::string(toString(c.kind)) + " " + std::to_string(c.size); }

double avgObstacleFraction(const ScaleCase& c) {
  double sum = 0.0;
  for (const GeneratedMap& g : c.maps) sum += g.obstacle_fraction;
  return c.maps.empty() ? 0.0 : sum / static_cast<double>(c.maps.size());
}

double avgOptimum(const ScaleCase& c) {
  double sum = 0.0;
  for (const GeneratedMap& g : c.maps) sum += g.optimum;
  return c.maps.empty() ? 0.0 : sum / static_cast<double>(c.maps.size());
}

// "12.3" or "—" when the variant did not run; "*" marks fewer runs than seeds.
std::string timeCell(const ScaleCase& c, VariantKey key) {
  const ScaleVariantResult* v = findVariant(c, key);
  if (v == nullptr || v->runs.empty()) return "—";
  std::string text = fixed(v->summary.median_time_ms, v->summary.median_time_ms < 10 ? 2 : 0);
  if (v->summary.interrupted_runs > 0) text += " (capped)";
  else if (v->skipped_seeds > 0) text += " (" + std::to_string(v->runs.size()) + " run)";
  return text;
}

std::string memoryCell(const ScaleCase& c, VariantKey key) {
  const ScaleVariantResult* v = findVariant(c, key);
  if (v == nullptr || v->runs.empty()) return "—";
  return fixed(v->max_peak_rss_mb, 1) + " (" + fixed(v->max_plan_rss_mb, 1) + ")";
}

std::string successCell(const ScaleVariantResult* v) {
  if (v == nullptr || v->runs.empty()) return "—";
  return std::to_string(v->summary.successes) + "/" + std::to_string(v->summary.runs);
}

std::string gapCell(const ScaleVariantResult* v) {
  if (v == nullptr || v->summary.successes == 0) return "—";
  return fixed(v->avg_gap_pct, 2) + " / " + fixed(v->max_gap_pct, 2);
}

// "—" when nothing ran; iterations also when no run succeeded.
std::string numberCell(const ScaleVariantResult* v, double Summary::*field, int decimals) {
  if (v == nullptr || v->runs.empty()) return "—";
  if (field == &Summary::avg_iterations && v->summary.successes == 0) return "—";
  return fixed(v->summary.*field, decimals);
}

std::string timeTable(const std::vector<ScaleCase>& cases) {
  MarkdownTable table({"map", "seeds", "obstacles", "A* length", "A*", "EACI 1 thread", "EACI all cores",
                       "EACI early stop, 1 thread", "EACI early stop, all cores", "ACO 1 thread", "ACO all cores"});
  for (const ScaleCase& c : cases)
    table.addRow({caseName(c), std::to_string(c.maps.size()), fixed(avgObstacleFraction(c) * 100, 0) + " %",
                  fixed(avgOptimum(c), 1), timeCell(c, VariantKey::kAStar), timeCell(c, VariantKey::kEaci1t), timeCell(c, VariantKey::kEaciAll),
                  timeCell(c, VariantKey::kEaciEarly1t), timeCell(c, VariantKey::kEaciEarlyAll), timeCell(c, VariantKey::kAco1t),
                  timeCell(c, VariantKey::kAcoAll)});
  return table.render();
}

std::string memoryTable(const std::vector<ScaleCase>& cases) {
  MarkdownTable table({"map", "A*", "EACI 1 thread", "EACI all cores", "EACI early stop, 1 thread", "ACO 1 thread",
                       "ACO all cores"});
  for (const ScaleCase& c : cases)
    table.addRow({caseName(c), memoryCell(c, VariantKey::kAStar), memoryCell(c, VariantKey::kEaci1t), memoryCell(c, VariantKey::kEaciAll),
                  memoryCell(c, VariantKey::kEaciEarly1t), memoryCell(c, VariantKey::kAco1t), memoryCell(c, VariantKey::kAcoAll)});
  return table.render();
}

std::string qualityTable(const std::vector<ScaleCase>& cases) {
  MarkdownTable table({"map", "EACI success", "EACI gap avg / max %", "EACI iterations", "EACI lost ants",
                       "ACO success", "ACO gap avg / max %", "ACO iterations", "ACO lost ants"});
  for (const ScaleCase& c : cases) {
    const ScaleVariantResult* e = findVariant(c, VariantKey::kEaci1t);
    const ScaleVariantResult* a = findVariant(c, VariantKey::kAco1t);
    table.addRow({caseName(c), successCell(e), gapCell(e), numberCell(e, &Summary::avg_iterations, 1),
                  numberCell(e, &Summary::avg_lost_ants, 1), successCell(a), gapCell(a),
                  numberCell(a, &Summary::avg_iterations, 1), numberCell(a, &Summary::avg_lost_ants, 0)});
  }
  return table.render();
}

std::string earlyStopTable(const std::vector<ScaleCase>& cases, int early_stop_iterations) {
  MarkdownTable table({"map", "A* ms", "EACI full ms", "EACI early-stop ms", "time saved", "length cost",
                       "early-stop gap to A*", "iterations run", "early stop ÷ A*", "set-up + 1st iteration ms"});
  for (const ScaleCase& c : cases) {
    const EarlyStopComparison e = compareEarlyStop(c, VariantKey::kEaci1t, VariantKey::kEaciEarly1t);
    if (e.seeds == 0) continue;
    table.addRow({caseName(c), fixed(e.astar_ms, 2), fixed(e.full_ms, 1), fixed(e.early_ms, 1),
                  fixed(e.time_saved_pct, 0) + " %", fixed(e.length_cost_pct, 2) + " %",
                  fixed(e.early_gap_pct, 2) + " %", fixed(e.early_iterations, 1), ratio(e.early_ms, e.astar_ms),
                  fixed(e.first_iteration_ms, 1)});
  }
  std::ostringstream s;
  s << "One thread; early stop after " << early_stop_iterations
    << " iterations without improvement; wall times are means over the seeds; *length cost*: "
       "early-stopped route over the full run's route, same seed; *set-up + 1st iteration*: wall time "
       "until the first iteration ended (islands, distance fields, initial pheromone, "
    << eaci::Parameters{}.ants << " ants).\n\n"
    << table.render();
  return s.str();
}

std::string notesList(const std::vector<ScaleCase>& cases) {
  std::ostringstream s;
  for (const ScaleCase& c : cases)
    for (const std::string& note : c.notes) s << "- " << caseName(c) << ": " << note << "\n";
  return s.str();
}

nlohmann::json runJson(const ScaleRun& run) {
  nlohmann::json j = toJson(run.record, false, false);
  j["optimum"] = run.optimum;
  j["gap_pct"] = eaci::report::finiteOrNull(run.gap_pct);
  j["peak_rss_mb"] = run.peak_rss_mb;
  j["plan_rss_mb"] = run.plan_rss_mb;
  return j;
}

nlohmann::json variantJson(const ScaleVariantResult& v) {
  nlohmann::json runs = nlohmann::json::array();
  for (const ScaleRun& run : v.runs) runs.push_back(runJson(run));
  return {{"key", toString(v.variant.key)},
          {"label", v.variant.label},
          {"algorithm", eaci::toString(v.variant.algorithm)},
          {"threads", v.variant.threads},
          {"early_stop_iterations", v.variant.early_stop_iterations},
          {"summary", v.summary},
          {"avg_gap_pct", eaci::report::finiteOrNull(v.avg_gap_pct)},
          {"max_gap_pct", eaci::report::finiteOrNull(v.max_gap_pct)},
          {"max_peak_rss_mb", v.max_peak_rss_mb},
          {"max_plan_rss_mb", v.max_plan_rss_mb},
          {"skipped_seeds", v.skipped_seeds},
          {"runs", runs}};
}

nlohmann::json caseJson(const ScaleCase& c) {
  nlohmann::json maps = nlohmann::json::array();
  for (const GeneratedMap& g : c.maps)
    maps.push_back({{"seed", g.seed}, {"seed_used", g.seed_used}, {"obstacle_fraction", g.obstacle_fraction},
                    {"optimum", g.optimum}});
  nlohmann::json variants = nlohmann::json::array();
  for (const ScaleVariantResult& v : c.variants) variants.push_back(variantJson(v));
  return {{"size", c.size},
          {"kind", toString(c.kind)},
          {"maps", maps},
          {"variants", variants},
          {"early_stop", compareEarlyStop(c, VariantKey::kEaci1t, VariantKey::kEaciEarly1t)},
          {"early_stop_all_cores", compareEarlyStop(c, VariantKey::kEaciAll, VariantKey::kEaciEarlyAll)},
          {"notes", c.notes}};
}

// Seed 1's map and every planner's route, for the plots.
nlohmann::json exampleJson(const ScaleCase& c) {
  const GeneratedMap& g = c.maps.front();
  nlohmann::json routes = nlohmann::json::object();
  for (const ScaleVariantResult& v : c.variants) {
    const ScaleRun* run = runWithSeed(&v, 1);
    if (run != nullptr && !run->record.path.empty()) routes[toString(v.variant.key)] = run->record.path;
  }
  return {{"size", c.size},      {"kind", toString(c.kind)},      {"seed", g.seed_used},
          {"grid", gridRows(g.map)}, {"start", g.start}, {"goal", g.goal},
          {"optimum", g.optimum}, {"routes", routes}};
}

}  // namespace

EarlyStopComparison compareEarlyStop(const ScaleCase& c, VariantKey full_key, VariantKey early_key) {
  EarlyStopComparison e;
  const ScaleVariantResult* full = findVariant(c, full_key);
  const ScaleVariantResult* early = findVariant(c, early_key);
  const ScaleVariantResult* astar = findVariant(c, VariantKey::kAStar);
  if (early == nullptr) return e;
  double cost = 0.0, gap = 0.0, iterations = 0.0;
  for (const ScaleRun& run : early->runs) {
    const ScaleRun* f = runWithSeed(full, run.record.seed);
    const ScaleRun* a = runWithSeed(astar, run.record.seed);
    if (f == nullptr || a == nullptr || !f->record.success || !run.record.success) continue;
    ++e.seeds;
    e.full_ms += f->record.time_ms;
    e.early_ms += run.record.time_ms;
    e.astar_ms += a->record.time_ms;
    cost += (run.record.length / f->record.length - 1.0) * 100.0;
    gap += run.gap_pct;
    iterations += run.record.iterations_run;
    e.first_iteration_ms += run.record.first_iteration_ms;
  }
  if (e.seeds == 0) return e;
  e.time_saved_pct = (1.0 - e.early_ms / e.full_ms) * 100.0;
  e.full_ms /= e.seeds;
  e.early_ms /= e.seeds;
  e.astar_ms /= e.seeds;
  e.length_cost_pct = cost / e.seeds;
  e.early_gap_pct = gap / e.seeds;
  e.early_iterations = iterations / e.seeds;
  e.first_iteration_ms /= e.seeds;
  return e;
}

nlohmann::json scaleJson(const std::vector<ScaleCase>& cases, const ScaleOptions& options,
                         const Provenance& provenance) {
  nlohmann::json out_cases = nlohmann::json::array();
  nlohmann::json examples = nlohmann::json::array();
  for (const ScaleCase& c : cases) {
    out_cases.push_back(caseJson(c));
    if (!c.maps.empty() && !c.maps.front().map.cells.empty()) examples.push_back(exampleJson(c));
  }
  std::vector<std::string> kinds;
  for (MapKind k : options.kinds) kinds.push_back(toString(k));
  return {{"kind", "scale"},
          {"provenance", provenance},
          {"settings",
           {{"sizes", options.sizes},
            {"kinds", kinds},
            {"runs", options.runs},
            {"budget_s", options.budget_s},
            {"slow_run_s", options.slow_run_s},
            {"early_stop_iterations", options.early_stop_iterations},
            {"parameters", eaci::report::parametersToJson(eaci::Parameters{})}}},
          {"cases", out_cases},
          {"examples", examples}};
}

std::string scaleCsv(const std::vector<ScaleCase>& cases) {
  CsvTable csv({"kind", "size", "algorithm", "threads", "early_stop_iterations", "runs", "skipped_seeds",
                "successes", "interrupted_runs", "avg_time_ms", "median_time_ms", "median_cpu_ms", "avg_time_to_best_ms",
                "avg_gap_pct", "max_gap_pct", "avg_iterations", "avg_iterations_run", "avg_lost_ants",
                "max_peak_rss_mb", "max_plan_rss_mb"});
  for (const ScaleCase& c : cases)
    for (const ScaleVariantResult& v : c.variants) {
      const Summary& s = v.summary;
      csv.addRow({toString(c.kind), std::to_string(c.size), toString(v.variant.key), std::to_string(v.variant.threads),
                  std::to_string(v.variant.early_stop_iterations), std::to_string(s.runs),
                  std::to_string(v.skipped_seeds), std::to_string(s.successes), std::to_string(s.interrupted_runs),
                  csvNumber(s.avg_time_ms), csvNumber(s.median_time_ms), csvNumber(s.median_cpu_ms),
                  csvNumber(s.avg_time_to_best_ms),
                  csvNumber(v.avg_gap_pct), csvNumber(v.max_gap_pct), csvNumber(s.avg_iterations),
                  csvNumber(s.avg_iterations_run), csvNumber(s.avg_lost_ants), csvNumber(v.max_peak_rss_mb),
                  csvNumber(v.max_plan_rss_mb)});
    }
  return csv.render();
}

std::string scaleMarkdown(const std::vector<ScaleCase>& cases, const ScaleOptions& options,
                          const Provenance& provenance) {
  std::ostringstream s;
  s << "## Scale: generated maps, the robot's move rule\n\n"
    << provenanceMarkdown(provenance) << "\n"
    << "Rooms (rooms 10–20 cells, 1-cell walls, a 2–3-cell door into each neighbour) and clutter "
       "(rectangular blocks over 20–30 % of the map) maps, start at the top-left corner, goal at the "
       "bottom-right; corner cutting forbidden; default parameters ("
    << eaci::toString(eaci::Parameters{}.island_strategy) << " islands, "
    << symbolValues(eaci::Parameters{}, {"ants", "max_iterations"})
    << "). Each plan runs in its own child process. Colony runs stop after "
    << options.budget_s << " s (marked *capped*); a planner whose run takes over " << options.slow_run_s
    << " s runs for the first seed only (marked *1 run*).\n\n"
    << "### Time per plan (ms of wall time, median over the seeds)\n\n"
    << timeTable(cases) << "\n"
    << "### Route quality (one thread)\n\n"
    << "*gap*: route length over the A* optimum of the same map, average and worst over the successful "
       "runs; *iterations*: iterations to converge.\n\n"
    << qualityTable(cases) << "\n"
    << "### Peak memory per plan (MiB)\n\n"
    << "The child process's peak resident set (`ru_maxrss` from `wait4`), worst over the seeds; in "
       "brackets what the plan added to the child's resident set at its start.\n\n"
    << memoryTable(cases) << "\n"
    << "### EACI with early stopping\n\n"
    << earlyStopTable(cases, options.early_stop_iterations) << "\n";
  const std::string notes = notesList(cases);
  if (!notes.empty()) s << "### Notes\n\n" << notes;
  return s.str();
}

}  // namespace eaci_bench
