// `eaci_bench scen FILE.scen`: a MovingAI benchmark scenario (eaci/io/movingai_scenario.hpp)
// on its .map files. Every K-th problem is planned by A* and by EACI with the project's
// defaults (corner cutting forbidden, the benchmarks' rule), in this process, one after the
// other: per problem the file's optimal length, A*'s length and its difference to it (more than
// kScenMismatchTolerance is a mismatch: a rule difference), EACI's length and gap, the times and
// their ratio; a summary over the problems. JSON, CSV and Markdown in --out.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "eaci/planner/parameters.hpp"
#include "eaci/io/movingai_scenario.hpp"
#include "run_record.hpp"

namespace eaci_bench {

// |A* - the file's optimal length| above this is a mismatch.
constexpr double kScenMismatchTolerance = 1e-4;

struct ScenOptions {
  std::string scen_path;
  int every = 1;              // problems 0, K, 2K, ... of the file (0-based)
  std::string map_dir;        // empty: the .scen file's directory
  std::string out_dir = "out/bench";
  int seeds = 1;              // EACI runs per problem, seeds 1..N
  double budget_s = 60.0;     // wall-time cap of one EACI run
  std::string params_path;    // --params: EACI's parameters from this flat YAML; empty: the defaults
  eaci::Parameters parameters;  // what A* and EACI run with (corner cutting always forbidden)
  std::string command_line;
};

struct ScenProblemResult {
  std::size_t index = 0;      // 0-based among the file's problems
  eaci::ScenarioProblem problem;
  std::string map_path;       // as opened
  RunRecord astar;
  double astar_diff = 0.0;    // A* length - optimal length (+inf when A* found no route)
  bool mismatch = false;      // |astar_diff| > kScenMismatchTolerance
  std::vector<RunRecord> eaci;  // one per seed
  int eaci_successes = 0;
  double eaci_length = 0.0;   // mean over successful seeds (+inf if none)
  double eaci_gap_pct = 0.0;  // mean gap of the successful seeds to the optimal length, %
  double eaci_worst_gap_pct = 0.0;
  double eaci_time_ms = 0.0;  // median over the seeds
  double time_ratio = 0.0;    // eaci_time_ms / A* time
};

struct ScenSummary {
  std::size_t problems_in_file = 0;
  std::size_t problems_run = 0;
  int mismatches = 0;
  int astar_failures = 0;
  int eaci_runs = 0;
  int eaci_failures = 0;
  int eaci_optimal_runs = 0;   // within kScenMismatchTolerance of the optimal length
  double median_gap_pct = 0.0; // over the problems' mean gaps (problems EACI solved)
  double mean_gap_pct = 0.0;
  double worst_gap_pct = 0.0;  // over every successful EACI run
  double median_time_ratio = 0.0;
  double astar_total_ms = 0.0;
  double eaci_total_ms = 0.0;  // all seeds
  double wall_s = 0.0;
};

struct ScenResult {
  std::vector<ScenProblemResult> problems;
  ScenSummary summary;
};

// Runs the scenario (throws std::runtime_error naming the file and line on a problem that does
// not fit its map: wrong map size, start or goal off the map or blocked).
ScenResult runScenario(const ScenOptions& options);
ScenSummary summarizeScenario(const std::vector<ScenProblemResult>& problems, std::size_t problems_in_file);

int runScenCommand(const ScenOptions& options);

}  // namespace eaci_bench
