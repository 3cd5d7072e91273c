#include "scen_report.hpp"

#include <sstream>

#include "common/json_number.hpp"
#include "common/parameters_json.hpp"
#include "report_format.hpp"
#include "scen_bands.hpp"

namespace eaci_bench {

namespace {

using eaci::report::finiteOrNull;

std::string xy(const eaci::Cell& c) { return std::to_string(c.col) + "," + std::to_string(c.row); }

// Times below 10 ms with two decimals.
std::string ms(double value) { return fixed(value, value < 10 ? 2 : 1); }

nlohmann::json summaryJson(const ScenSummary& s) {
  return {{"problems_in_file", s.problems_in_file},
          {"problems_run", s.problems_run},
          {"mismatches", s.mismatches},
          {"astar_failures", s.astar_failures},
          {"eaci_runs", s.eaci_runs},
          {"eaci_failures", s.eaci_failures},
          {"eaci_optimal_runs", s.eaci_optimal_runs},
          {"median_gap_pct", finiteOrNull(s.median_gap_pct)},
          {"mean_gap_pct", finiteOrNull(s.mean_gap_pct)},
          {"worst_gap_pct", finiteOrNull(s.worst_gap_pct)},
          {"median_time_ratio", finiteOrNull(s.median_time_ratio)},
          {"astar_total_ms", s.astar_total_ms},
          {"eaci_total_ms", s.eaci_total_ms},
          {"wall_s", s.wall_s}};
}

std::string lengthRange(const ScenLengthBand& b) { return fixed(b.lower, 0) + "–" + fixed(b.upper, 0); }

nlohmann::json bandsJson(const std::vector<ScenLengthBand>& bands) {
  nlohmann::json out = nlohmann::json::array();
  for (const ScenLengthBand& b : bands)
    out.push_back({{"optimal_length_from", b.lower},
                   {"optimal_length_below", b.upper},
                   {"problems", b.problems},
                   {"eaci_runs", b.eaci_runs},
                   {"eaci_failures", b.eaci_failures},
                   {"median_time_ratio", finiteOrNull(b.median_time_ratio)},
                   {"max_time_ratio", finiteOrNull(b.max_time_ratio)},
                   {"median_gap_pct", finiteOrNull(b.median_gap_pct)},
                   {"worst_gap_pct", finiteOrNull(b.worst_gap_pct)},
                   {"median_astar_ms", b.median_astar_ms},
                   {"median_eaci_ms", b.median_eaci_ms}});
  return out;
}

nlohmann::json problemJson(const ScenProblemResult& r) {
  nlohmann::json eaci = nlohmann::json::array();
  for (const RunRecord& run : r.eaci) eaci.push_back(toJson(run, false, false));
  return {{"index", r.index},
          {"line", r.problem.line},
          {"bucket", r.problem.bucket},
          {"map", r.problem.map},
          {"start_xy", {r.problem.start.col, r.problem.start.row}},
          {"goal_xy", {r.problem.goal.col, r.problem.goal.row}},
          {"optimal_length", r.problem.optimal_length},
          {"astar_length", finiteOrNull(r.astar.success ? r.astar.length : std::numeric_limits<double>::infinity())},
          {"astar_diff", finiteOrNull(r.astar_diff)},
          {"mismatch", r.mismatch},
          {"astar_time_ms", r.astar.time_ms},
          {"eaci_successes", r.eaci_successes},
          {"eaci_length", finiteOrNull(r.eaci_length)},
          {"eaci_gap_pct", finiteOrNull(r.eaci_gap_pct)},
          {"eaci_worst_gap_pct", finiteOrNull(r.eaci_worst_gap_pct)},
          {"eaci_time_ms", r.eaci_time_ms},
          {"time_ratio", finiteOrNull(r.time_ratio)},
          {"eaci_runs", eaci}};
}

}  // namespace

nlohmann::json scenJson(const ScenResult& result, const ScenOptions& options, const Provenance& provenance) {
  nlohmann::json problems = nlohmann::json::array();
  for (const ScenProblemResult& r : result.problems) problems.push_back(problemJson(r));
  return {{"command", "scen"},
          {"scenario", options.scen_path},
          {"options",
           {{"every", options.every}, {"map_dir", options.map_dir}, {"seeds", options.seeds}, {"budget_s", options.budget_s}}},
          {"mismatch_tolerance", kScenMismatchTolerance},
          {"parameters", eaci::report::parametersToJson(options.parameters)},
          {"provenance", provenance},
          {"summary", summaryJson(result.summary)},
          {"length_bands", bandsJson(lengthBands(result.problems))},
          {"problems", problems}};
}

std::string scenCsv(const ScenResult& result) {
  CsvTable table({"index", "line", "bucket", "map", "start_x", "start_y", "goal_x", "goal_y", "optimal_length",
                  "astar_length", "astar_diff", "mismatch", "astar_time_ms", "eaci_runs", "eaci_successes",
                  "eaci_length", "eaci_gap_pct", "eaci_worst_gap_pct", "eaci_time_ms", "time_ratio"});
  for (const ScenProblemResult& r : result.problems) {
    const eaci::ScenarioProblem& p = r.problem;
    table.addRow({std::to_string(r.index), std::to_string(p.line), std::to_string(p.bucket), p.map,
                  std::to_string(p.start.col), std::to_string(p.start.row), std::to_string(p.goal.col),
                  std::to_string(p.goal.row), csvNumber(p.optimal_length),
                  csvNumber(r.astar.success ? r.astar.length : std::numeric_limits<double>::infinity()),
                  csvNumber(r.astar_diff), r.mismatch ? "1" : "0", csvNumber(r.astar.time_ms),
                  std::to_string(r.eaci.size()), std::to_string(r.eaci_successes), csvNumber(r.eaci_length),
                  csvNumber(r.eaci_gap_pct), csvNumber(r.eaci_worst_gap_pct), csvNumber(r.eaci_time_ms),
                  csvNumber(r.time_ratio)});
  }
  return table.render();
}

std::string scenSummaryLine(const ScenSummary& s) {
  std::ostringstream line;
  line << s.problems_run << " of " << s.problems_in_file << " problems, " << s.mismatches << " A* mismatches, EACI "
       << (s.eaci_runs - s.eaci_failures) << "/" << s.eaci_runs << " solved (" << s.eaci_optimal_runs
       << " optimal), gap median " << fixed(s.median_gap_pct, 2) << " % worst " << fixed(s.worst_gap_pct, 2)
       << " %, time EACI/A* median " << fixed(s.median_time_ratio, 1) << "x";
  return line.str();
}

std::string scenMarkdown(const ScenResult& result, const ScenOptions& options, const Provenance& provenance) {
  const ScenSummary& s = result.summary;
  std::ostringstream md;
  md << "# MovingAI scenario " << options.scen_path << "\n\n";
  md << provenanceMarkdown(provenance) << "\n";
  md << (options.every == 1 ? std::string("Every problem") : "Every " + std::to_string(options.every) + "-th problem (1, " +
                                                              std::to_string(1 + options.every) + ", ...)")
     << "; A* once, EACI ("
     << (options.params_path.empty() ? std::string("the project's defaults") : "parameters of " + options.params_path)
     << ", corner cutting forbidden) with seeds 1.." << options.seeds << ", at most " << fixed(options.budget_s, 0)
     << " s a run. Gap: EACI's length over the file's optimal length; a mismatch: |A* - optimal| > "
     << kScenMismatchTolerance << ".\n\n";
  MarkdownTable summary({"problems run", "A* mismatches", "EACI solved", "EACI optimal", "gap median", "gap mean",
                         "gap worst", "time EACI/A* median", "A* total", "EACI total"});
  summary.addRow({std::to_string(s.problems_run) + " of " + std::to_string(s.problems_in_file),
                  std::to_string(s.mismatches), std::to_string(s.eaci_runs - s.eaci_failures) + "/" + std::to_string(s.eaci_runs),
                  std::to_string(s.eaci_optimal_runs), fixed(s.median_gap_pct, 2) + " %", fixed(s.mean_gap_pct, 2) + " %",
                  fixed(s.worst_gap_pct, 2) + " %", fixed(s.median_time_ratio, 1) + "×", ms(s.astar_total_ms) + " ms",
                  ms(s.eaci_total_ms) + " ms"});
  md << summary.render() << "\n";
  md << "By route length (bands of the optimal length, cells; times are medians over the band's problems):\n\n";
  MarkdownTable bands({"optimal length", "problems", "EACI solved", "time EACI/A* median", "EACI/A* worst",
                       "gap median", "gap worst", "A* ms", "EACI ms"});
  for (const ScenLengthBand& b : lengthBands(result.problems))
    bands.addRow({lengthRange(b), std::to_string(b.problems),
                  std::to_string(b.eaci_runs - b.eaci_failures) + "/" + std::to_string(b.eaci_runs),
                  fixed(b.median_time_ratio, 2) + "×", fixed(b.max_time_ratio, 2) + "×",
                  fixed(b.median_gap_pct, 2) + " %", fixed(b.worst_gap_pct, 2) + " %", ms(b.median_astar_ms),
                  ms(b.median_eaci_ms)});
  md << bands.render() << "\n";
  MarkdownTable table({"#", "bucket", "start (x,y)", "goal (x,y)", "optimal", "A*", "A* − opt", "EACI", "gap %",
                       "A* ms", "EACI ms", "EACI/A*"});
  for (const ScenProblemResult& r : result.problems) {
    table.addRow({std::to_string(r.index + 1) + (r.mismatch ? " **mismatch**" : ""), std::to_string(r.problem.bucket),
                  xy(r.problem.start), xy(r.problem.goal), fixed(r.problem.optimal_length, 4),
                  r.astar.success ? fixed(r.astar.length, 4) : "no route", fixed(r.astar_diff, 6), fixed(r.eaci_length, 4),
                  fixed(r.eaci_gap_pct, 2), ms(r.astar.time_ms), ms(r.eaci_time_ms), fixed(r.time_ratio, 1) + "×"});
  }
  md << table.render();
  return md.str();
}

}  // namespace eaci_bench
