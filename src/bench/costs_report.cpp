#include "costs_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "common/json_number.hpp"
#include "common/parameters_json.hpp"
#include "report_format.hpp"

namespace eaci_bench {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

using eaci::report::finiteOrNull;

const CostVariantRuns* findVariant(const CostProblem& p, VariantKey key) {
  for (const CostVariantRuns& v : p.variants)
    if (v.variant.key == key) return &v;
  return nullptr;
}

std::vector<const CostProblem*> problemsOf(const CostGroup& g) {
  std::vector<const CostProblem*> out;
  for (const CostProblem& p : g.problems) out.push_back(&p);
  return out;
}

std::string labelOf(VariantKey key) {
  for (const CostVariant& v : costVariants())
    if (v.key == key) return v.label;
  return toString(key);
}

// "0.12 / 0.80"; signed when a gap can be negative (smoothed routes cost less than A*'s grid route).
std::string gapCell(const GapSummary& g) {
  if (g.count == 0) return "—";
  return fixed(g.median, 2) + " / " + fixed(g.worst, 2);
}

std::string cellsCell(const CostVariantSummary& s) {
  return std::to_string(s.lethal_cells) + " / " + std::to_string(s.inscribed_cells);
}

std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0e", x);
  return text;
}

std::string timeText(double ms) { return fixed(ms, ms < 10 ? 2 : (ms < 100 ? 1 : 0)); }

std::string ratioText(double r) { return std::isfinite(r) ? fixed(r, r < 10 ? 2 : 1) + "×" : "—"; }

std::string verdict(const GapSummary& g) {
  if (g.count == 0) return "no runs";
  const bool median_ok = g.median <= 1.0, worst_ok = g.worst <= 3.0;
  if (median_ok && worst_ok) return "met";
  std::string why;
  if (!median_ok) why += "median " + fixed(g.median, 2) + " % > 1 %";
  if (!worst_ok) why += std::string(why.empty() ? "" : ", ") + "worst " + fixed(g.worst, 2) + " % > 3 %";
  return "**missed** (" + why + ")";
}

std::vector<VariantKey> keys() {
  std::vector<VariantKey> out;
  for (const CostVariant& v : costVariants()) out.push_back(v.key);
  return out;
}

std::string describeInflation(const eaci::InflationParameters& p, const char* unit) {
  std::ostringstream s;
  s << "inflation radius " << p.inflation_radius << " " << unit << ", inscribed radius " << p.inscribed_radius << " "
    << unit << ", cost_scaling_factor " << p.cost_scaling_factor << " per " << unit;
  return s.str();
}

std::string verdictTable(const std::vector<CostGroup>& groups) {
  MarkdownTable table({"maps", "problems", "runs per planner", "A* = Dijkstra (worst rel. diff.)",
                       "EACI gap median / worst %", "EACI: median ≤ 1 %, worst ≤ 3 %",
                       "routes in lethal / inscribed cells (all planners)", "EACI ÷ A* time (median)",
                       "EACI smoothed ÷ A* time", "EACI smoothed gap median / worst %", "turning: EACI smoothed ÷ EACI"});
  for (const CostGroup& g : groups) {
    const auto problems = problemsOf(g);
    const CostVariantSummary e = summarizeVariant(problems, VariantKey::kEaci1t);
    const CostVariantSummary es = summarizeVariant(problems, VariantKey::kEaciSmoothed1t);
    int in_lethal = 0;
    for (VariantKey key : keys()) in_lethal += summarizeVariant(problems, key).routes_in_lethal;
    const double diff = worstAStarDijkstraDifference(g);
    table.addRow({g.name, std::to_string(g.problems.size()), std::to_string(e.runs),
                  diff <= 1e-9 ? (diff == 0 ? std::string("yes (identical)") : "yes (≤ " + scientific(diff) + ")")
                               : "**no** (" + fixed(diff * 100, 4) + " %)",
                  gapCell(e.gap), verdict(e.gap), std::to_string(in_lethal), ratioText(e.median_time_ratio),
                  ratioText(es.median_time_ratio), gapCell(es.gap), ratio(es.median_turn_deg, e.median_turn_deg)});
  }
  return table.render();
}

std::string labTable(const CostGroup& g) {
  MarkdownTable table({"start → goal (m)", "planner", "cost", "gap median / worst %", "length m", "turning °",
                       "min clearance m", "mean cell cost", "lethal / inscribed cells", "ms", "÷ A*"});
  for (const CostProblem& p : g.problems) {
    bool first = true;
    for (VariantKey key : keys()) {
      const CostVariantSummary s = summarizeVariant({&p}, key);
      const CostVariantRuns* v = findVariant(p, key);
      std::vector<double> costs;
      if (v)
        for (const CostRun& run : v->runs) costs.push_back(run.driven.cost);
      table.addRow({first ? p.name : "", labelOf(key), fixed(medianOf(costs), 2), gapCell(s.gap),
                    fixed(s.median_length * g.resolution, 2), fixed(s.median_turn_deg, 0),
                    fixed(s.min_clearance * g.resolution, 3), fixed(s.median_mean_cell_cost, 1), cellsCell(s),
                    timeText(s.median_time_ms), ratioText(s.median_time_ratio)});
      first = false;
    }
  }
  return table.render();
}

std::string generatedTable(const std::vector<CostGroup>& groups) {
  MarkdownTable table({"map", "blocked after inflation", "planner", "routes", "gap median / worst %", "length",
                       "turning °", "min clearance worst / median", "mean cell cost", "lethal / inscribed cells",
                       "ms", "÷ A*", "peak MiB"});
  for (const CostGroup& g : groups) {
    if (g.lab) continue;
    double obstacles = 0, blocked = 0;
    for (const CostProblem& p : g.problems) {
      obstacles += p.obstacle_fraction;
      blocked += p.blocked_fraction;
    }
    const double n = std::max<double>(1, static_cast<double>(g.problems.size()));
    bool first = true;
    for (VariantKey key : keys()) {
      const CostVariantSummary s = summarizeVariant(problemsOf(g), key);
      std::string routes = std::to_string(s.successes) + "/" + std::to_string(s.runs);
      if (s.capped > 0) routes += " (" + std::to_string(s.capped) + " capped)";
      table.addRow({first ? g.name : "", first ? fixed(obstacles / n * 100, 0) + " → " + fixed(blocked / n * 100, 0) + " %" : "",
                    labelOf(key), routes, gapCell(s.gap), fixed(s.median_length, 1), fixed(s.median_turn_deg, 0),
                    fixed(s.min_clearance, 2) + " / " + fixed(s.median_clearance, 2), fixed(s.median_mean_cell_cost, 1),
                    cellsCell(s), timeText(s.median_time_ms), ratioText(s.median_time_ratio), fixed(s.max_peak_rss_mb, 1)});
      first = false;
    }
  }
  return table.render();
}

nlohmann::json checkJson(const RouteCheck& c) {
  return {{"cost", finiteOrNull(c.cost)},
          {"length", finiteOrNull(c.length)},
          {"turn_deg", c.turn_deg},
          {"min_clearance", finiteOrNull(c.min_clearance)},
          {"mean_cell_cost", finiteOrNull(c.mean_cell_cost)},
          {"lethal_cells", c.lethal_cells},
          {"inscribed_cells", c.inscribed_cells}};
}

nlohmann::json summaryJson(const CostVariantSummary& s) {
  return {{"runs", s.runs},
          {"successes", s.successes},
          {"capped", s.capped},
          {"gap_median_pct", finiteOrNull(s.gap.median)},
          {"gap_worst_pct", finiteOrNull(s.gap.worst)},
          {"median_time_ms", s.median_time_ms},
          {"median_time_ratio", finiteOrNull(s.median_time_ratio)},
          {"median_length", finiteOrNull(s.median_length)},
          {"median_turn_deg", finiteOrNull(s.median_turn_deg)},
          {"min_clearance", finiteOrNull(s.min_clearance)},
          {"median_clearance", finiteOrNull(s.median_clearance)},
          {"median_mean_cell_cost", finiteOrNull(s.median_mean_cell_cost)},
          {"lethal_cells", s.lethal_cells},
          {"inscribed_cells", s.inscribed_cells},
          {"routes_in_lethal", s.routes_in_lethal},
          {"max_peak_rss_mb", s.max_peak_rss_mb}};
}

nlohmann::json problemJson(const CostProblem& p) {
  nlohmann::json variants = nlohmann::json::array();
  for (const CostVariantRuns& v : p.variants) {
    nlohmann::json runs = nlohmann::json::array();
    for (const CostRun& run : v.runs) {
      nlohmann::json j = toJson(run.record, false, !run.record.path.empty());
      j["driven"] = checkJson(run.driven);
      j["gap_pct"] = finiteOrNull(run.gap_pct);
      j["time_ratio"] = finiteOrNull(run.time_ratio);
      j["peak_rss_mb"] = run.peak_rss_mb;
      j["same_grid_route"] = run.same_grid_route;
      runs.push_back(std::move(j));
    }
    variants.push_back({{"key", toString(v.variant.key)},
                        {"label", v.variant.label},
                        {"algorithm", eaci::toString(v.variant.algorithm)},
                        {"smooth_path", v.variant.smooth},
                        {"summary", summaryJson(summarizeVariant({&p}, v.variant.key))},
                        {"runs", runs}});
  }
  nlohmann::json j = {{"name", p.name},
                      {"map_seed", p.map_seed},
                      {"map_seed_used", p.map_seed_used},
                      {"start", p.start},
                      {"goal", p.goal},
                      {"astar_cost", finiteOrNull(p.astar_cost)},
                      {"dijkstra_cost", finiteOrNull(p.dijkstra_cost)},
                      {"obstacle_fraction", p.obstacle_fraction},
                      {"blocked_fraction", p.blocked_fraction},
                      {"variants", variants}};
  if (!p.example_costs.bytes.empty()) {
    nlohmann::json rows = nlohmann::json::array();
    for (int r = 0; r < p.example_costs.height; ++r) {
      const auto begin = p.example_costs.bytes.begin() + static_cast<std::ptrdiff_t>(r) * p.example_costs.width;
      rows.push_back(std::vector<int>(begin, begin + p.example_costs.width));
    }
    j["example_costs"] = std::move(rows);
  }
  return j;
}

}  // namespace

CostVariantSummary summarizeVariant(const std::vector<const CostProblem*>& problems, VariantKey key) {
  CostVariantSummary s;
  std::vector<double> gaps, times, ratios, lengths, turns, clearances, mean_costs;
  for (const CostProblem* p : problems) {
    const CostVariantRuns* v = findVariant(*p, key);
    if (v == nullptr) continue;
    for (const CostRun& run : v->runs) {
      ++s.runs;
      times.push_back(run.record.time_ms);
      ratios.push_back(run.time_ratio);
      s.max_peak_rss_mb = std::max(s.max_peak_rss_mb, run.peak_rss_mb);
      if (run.record.interrupted) ++s.capped;
      gaps.push_back(run.gap_pct);  // +infinity for a failure: the worst
      if (!run.record.success) continue;
      ++s.successes;
      lengths.push_back(run.driven.length);
      turns.push_back(run.driven.turn_deg);
      clearances.push_back(run.driven.min_clearance);
      mean_costs.push_back(run.driven.mean_cell_cost);
      s.lethal_cells += run.driven.lethal_cells;
      s.inscribed_cells += run.driven.inscribed_cells;
      if (run.driven.lethal_cells + run.driven.inscribed_cells > 0) ++s.routes_in_lethal;
    }
  }
  s.gap = summarizeGaps(gaps);
  s.median_time_ms = medianOf(times);
  s.median_time_ratio = medianOf(ratios);
  s.median_length = medianOf(lengths);
  s.median_turn_deg = medianOf(turns);
  s.min_clearance = clearances.empty() ? kInfinity : *std::min_element(clearances.begin(), clearances.end());
  s.median_clearance = medianOf(clearances);
  s.median_mean_cell_cost = medianOf(mean_costs);
  return s;
}

double worstAStarDijkstraDifference(const CostGroup& group) {
  double worst = 0.0;
  for (const CostProblem& p : group.problems) {
    const double diff = std::abs(p.astar_cost - p.dijkstra_cost) / std::max(1e-12, p.dijkstra_cost);
    worst = std::max(worst, std::isfinite(diff) ? diff : kInfinity);
  }
  return worst;
}

nlohmann::json costsJson(const std::vector<CostGroup>& groups, const CostsOptions& options, const Provenance& provenance) {
  nlohmann::json out = nlohmann::json::array();
  for (const CostGroup& g : groups) {
    nlohmann::json problems = nlohmann::json::array();
    for (const CostProblem& p : g.problems) problems.push_back(problemJson(p));
    nlohmann::json summaries = nlohmann::json::object();
    for (VariantKey key : keys()) summaries[toString(key)] = summaryJson(summarizeVariant(problemsOf(g), key));
    out.push_back({{"name", g.name},
                   {"lab", g.lab},
                   {"kind", g.lab ? "lab" : toString(g.kind)},
                   {"size", g.size},
                   {"resolution", g.resolution},
                   {"astar_dijkstra_worst_rel_diff", finiteOrNull(worstAStarDijkstraDifference(g))},
                   {"summaries", summaries},
                   {"problems", problems},
                   {"notes", g.notes}});
  }
  std::vector<std::string> kinds;
  for (MapKind k : options.kinds) kinds.push_back(toString(k));
  const auto inflation = [](const eaci::InflationParameters& p) {
    return nlohmann::json{{"inflation_radius", p.inflation_radius},
                          {"inscribed_radius", p.inscribed_radius},
                          {"cost_scaling_factor", p.cost_scaling_factor}};
  };
  return {{"kind", "costs"},
          {"provenance", provenance},
          {"settings",
           {{"sizes", options.sizes},
            {"kinds", kinds},
            {"runs", options.runs},
            {"lab_map", options.lab_map},
            {"lab_seeds", options.lab_seeds},
            {"budget_s", options.budget_s},
            {"lab_inflation_m", inflation(options.lab_inflation)},
            {"generated_inflation_cells", inflation(options.generated_inflation)},
            {"rooms_door_cells", {options.generator.door_min, options.generator.door_max}},
            {"parameters", eaci::report::parametersToJson(eaci::Parameters{})}}},
          {"groups", out}};
}

std::string costsCsv(const std::vector<CostGroup>& groups) {
  CsvTable csv({"group", "problem", "map_seed_used", "algorithm", "seed", "success", "interrupted", "cost", "astar_cost",
                "gap_pct", "length_cells", "turn_deg", "min_clearance_cells", "mean_cell_cost", "lethal_cells",
                "inscribed_cells", "time_ms", "time_ratio_to_astar", "peak_rss_mb", "iterations_run"});
  for (const CostGroup& g : groups)
    for (const CostProblem& p : g.problems)
      for (const CostVariantRuns& v : p.variants)
        for (const CostRun& run : v.runs)
          csv.addRow({g.name, p.name, std::to_string(p.map_seed_used), toString(v.variant.key),
                      std::to_string(run.record.seed), run.record.success ? "1" : "0", run.record.interrupted ? "1" : "0",
                      csvNumber(run.driven.cost), csvNumber(p.astar_cost), csvNumber(run.gap_pct), csvNumber(run.driven.length),
                      csvNumber(run.driven.turn_deg), csvNumber(run.driven.min_clearance),
                      csvNumber(run.driven.mean_cell_cost), std::to_string(run.driven.lethal_cells),
                      std::to_string(run.driven.inscribed_cells), csvNumber(run.record.time_ms),
                      csvNumber(run.time_ratio), csvNumber(run.peak_rss_mb), std::to_string(run.record.iterations_run)});
  return csv.render();
}

std::string costsMarkdown(const std::vector<CostGroup>& groups, const CostsOptions& options, const Provenance& provenance) {
  const eaci::Parameters defaults;
  std::ostringstream s;
  s << "## Cost-aware planning: inflated cost maps\n\n"
    << provenanceMarkdown(provenance) << "\n"
    << "Maps inflated with costmap_2d's formula (`eaci/grid/inflation.hpp`): cells within the inscribed radius "
       "of an obstacle cost 253 and are obstacles to the planners (`lethal_cost` 253), cells out to the inflation "
       "radius 252·exp(−cost_scaling_factor·(d − inscribed radius)); a move into a cell of cost c costs "
       "step × ("
    << defaults.neutral_cost << " + " << defaults.cost_factor << " c) / " << defaults.neutral_cost
    << " (global_planner's). The lab (`" << options.lab_map << "`): " << describeInflation(options.lab_inflation, "m")
    << " (`config/costmap_common_params.yaml`; the inscribed radius is the padded footprint's), "
    << options.lab_seeds << " seeds per start/goal pair. Generated maps (the `scale` generator, start top-left, goal "
       "bottom-right): "
    << describeInflation(options.generated_inflation, "cell")
    << ", rooms with doors of " << options.generator.door_min << "–" << options.generator.door_max
    << " cells; a map whose start and goal are not connected once inflated is drawn again. Default parameters, one "
       "thread, corner cutting forbidden; each plan in its own child process; colony runs stop after "
    << options.budget_s
    << " s (*capped*). *cost*: the route's cost — for a smoothed route the cost of its straight segments "
       "(the smoother's `segmentCost`), which smoothing never raises; *gap*: cost over A*'s cost on the same "
       "problem (negative: cheaper than A*'s 8-connected route), median / worst over the runs; *length*, "
       "*turning*: of the route the robot would drive (the smoothed one when smoothing is on); *min clearance*: "
       "nearest obstacle cell of the map (not inflated) to the centre of any cell the route crosses; *mean cell "
       "cost*: over those cells; *lethal / inscribed cells*: cells of cost 254–255 / 253 the route crosses or "
       "touches at a corner (should be 0 / 0); *÷ A\\**: wall time over A*'s on the same problem in the same run, "
       "median; *A\\* = Dijkstra*: A*'s cost against a weighted Dijkstra written independently "
       "(`src/bench/cost_checks.hpp`) on every map.\n\n"
    << "### Verdict per map set\n\n"
    << verdictTable(groups) << "\n";
  for (const CostGroup& g : groups)
    if (g.lab)
      s << "### Lab map (" << g.size << " cells wide, " << g.resolution << " m per cell)\n\n"
        << "Medians over " << options.lab_seeds << " seeds (A*: the same route each time).\n\n"
        << labTable(g) << "\n";
  s << "### Generated maps (lengths and clearances in cells)\n\n"
    << "*blocked after inflation*: obstacle cells of the map → cells of cost ≥ 253 after inflation (average over "
       "the seeds).\n\n"
    << generatedTable(groups) << "\n";
  std::ostringstream notes;
  for (const CostGroup& g : groups)
    for (const std::string& note : g.notes) notes << "- " << g.name << ": " << note << "\n";
  if (!notes.str().empty()) s << "### Notes\n\n" << notes.str();
  return s.str();
}

}  // namespace eaci_bench
