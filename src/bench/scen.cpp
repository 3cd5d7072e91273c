// `scen FILE.scen`: a MovingAI benchmark scenario (eaci/io/movingai_scenario.hpp) on its .map
// files. Every K-th problem is planned by A* and by EACI (seeds 1..N), in this process, each
// planner keeping its workspace from plan to plan as a robot's planner would.
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "eaci/io/map_io.hpp"
#include "eaci/io/movingai_scenario.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "studies.hpp"

namespace eaci_bench {

namespace {

// |A* - the file's optimal length| above this is a mismatch (a rule difference).
constexpr double kMismatchTolerance = 1e-4;

// The problem fits its map: sizes as written, start and goal on the map and passable.
void checkProblem(const std::string& scen, const eaci::ScenarioProblem& p, const eaci::OccupancyMap& map,
                  const std::string& map_path) {
  const std::string where = scen + ": line " + std::to_string(p.line) + ": ";
  if (p.map_width != map.width || p.map_height != map.height)
    throw std::runtime_error(where + "map size " + std::to_string(p.map_width) + " x " + std::to_string(p.map_height) +
                             " but " + map_path + " is " + std::to_string(map.width) + " x " + std::to_string(map.height));
  for (const auto& [name, cell] : {std::pair<const char*, eaci::Cell>{"start", p.start}, {"goal", p.goal}}) {
    const std::string at = std::string(name) + " (x " + std::to_string(cell.col) + ", y " + std::to_string(cell.row) + ")";
    if (cell.row >= map.height || cell.col >= map.width) throw std::runtime_error(where + at + " is off the map");
    if (!map.view().isFree(cell)) throw std::runtime_error(where + at + " is blocked in " + map_path);
  }
}

}  // namespace

int runScen(const ScenOptions& o, RecordWriter& out) {
  namespace fs = std::filesystem;
  Progress progress("scen");
  const std::vector<eaci::ScenarioProblem> problems = eaci::loadMovingAiScenario(o.scen_path);
  const fs::path dir = o.map_dir.empty() ? fs::path(o.scen_path).parent_path() : fs::path(o.map_dir);
  std::map<std::string, eaci::OccupancyMap> maps;
  eaci::PlannerWorkspace astar_workspace, eaci_workspace;
  const int chosen = static_cast<int>((problems.size() + static_cast<std::size_t>(o.every) - 1) / static_cast<std::size_t>(o.every));
  int mismatches = 0;
  for (std::size_t index = 0; index < problems.size(); index += static_cast<std::size_t>(o.every)) {
    const eaci::ScenarioProblem& p = problems[index];
    const std::string map_path = (dir / p.map).string();
    auto found = maps.find(map_path);
    if (found == maps.end()) found = maps.emplace(map_path, eaci::loadMap(map_path)).first;
    const eaci::OccupancyMap& m = found->second;
    checkProblem(o.scen_path, p, m, map_path);
    progress.show("problem " + std::to_string(index + 1) + " (bucket " + std::to_string(p.bucket) + ", " + p.map + ")",
                  static_cast<int>(index) / o.every + 1, chosen);
    Record r;
    r.map = p.map;
    r.problem = {{"scen", o.scen_path}, {"index", index}, {"line", p.line}, {"bucket", p.bucket},
                 {"problems_in_file", problems.size()}, {"start", p.start}, {"goal", p.goal},
                 {"optimal_length", p.optimal_length}};
    r.params = o.parameters;
    r.variant = "astar";
    r.run = timedPlan(TimedPlanRequest{m.view(), p.start, p.goal, eaci::Algorithm::kAStar, r.params, 0.0, &astar_workspace},
                      false, false);
    const bool success = r.run["success"].get<bool>();
    const double length = success ? r.run["length"].get<double>() : INFINITY;
    if (!(std::abs(length - p.optimal_length) <= kMismatchTolerance)) {
      ++mismatches;
      progress.note("mismatch on problem " + std::to_string(index + 1) + " (line " + std::to_string(p.line) +
                    "): optimal length " + std::to_string(p.optimal_length) + ", A* " +
                    (success ? std::to_string(length) : std::string("no route")));
    }
    out.append(r);
    r.variant = "eaci";
    for (int seed = 1; seed <= o.seeds; ++seed) {
      r.params.seed = static_cast<std::uint64_t>(seed);
      r.run = timedPlan(TimedPlanRequest{m.view(), p.start, p.goal, eaci::Algorithm::kEaci, r.params, o.budget_s * 1000.0,
                                    &eaci_workspace}, false, false);
      out.append(r);
    }
  }
  progress.finish();
  return mismatches;
}

}  // namespace eaci_bench
