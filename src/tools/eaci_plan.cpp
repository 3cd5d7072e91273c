// eaci_plan: plan one route on a map with EACI, classic ACO or A*, print a summary, and
// optionally write a JSON report and a PNG picture.
//
// Exit status: 0 path found, 2 bad input (arguments, map, parameters, start/goal), 3 no path,
// 4 stopped (SIGINT/SIGTERM) before a path was found; the JSON's "outcome" names it finer.
// Every failure prints one line "eaci_plan: error: <reason>" on stderr.

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "cli_args.hpp"
#include "eaci/aco/auxiliary_map.hpp"
#include "eaci/planner/parameters.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/end_headings.hpp"
#include "eaci/grid/cell_numbering.hpp"
#include "eaci/grid/inflation.hpp"
#include "eaci/grid/nearest_free.hpp"
#include "eaci/search/nearest_reachable.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/io/occupancy_map.hpp"
#include "eaci/planner/parameter_file.hpp"
#include "eaci/io/text.hpp"
#include "eaci/metrics/path_metrics.hpp"
#include "eaci/planner.hpp"
#include "plan_image.hpp"
#include "plan_json.hpp"

namespace {

using eaci::formatNumber;

// Exit status by outcome (the JSON's "outcome" names it finer): 0 a route; 2 bad input (the
// arguments, the map, the parameters, a start or goal off the map or in an obstacle); 3 no
// route joins a usable start and goal; 4 stopped (SIGINT/SIGTERM) before a route was found.
constexpr int kExitPath = 0;
constexpr int kExitBadInput = 2;
constexpr int kExitNoPath = 3;
constexpr int kExitStopped = 4;
constexpr const char* kErrorPrefix = "eaci_plan: error: ";

// Bad input found by the CLI itself (exit 2): the status plan() would give it, or none for the
// arguments themselves (the JSON's outcome "bad_input").
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message, std::optional<eaci::PlanStatus> status = std::nullopt)
      : std::runtime_error(message), status_(status) {}
  std::optional<eaci::PlanStatus> status() const { return status_; }

 private:
  std::optional<eaci::PlanStatus> status_;
};

// The exit status of a plan() that found no route: its status decides, never its sentence.
int exitCodeOf(eaci::PlanStatus status) {
  switch (status) {
    case eaci::PlanStatus::kSuccess: return kExitPath;
    case eaci::PlanStatus::kNoPath: return kExitNoPath;
    case eaci::PlanStatus::kStopped: return kExitStopped;
    case eaci::PlanStatus::kStartOffMap:
    case eaci::PlanStatus::kStartBlocked:
    case eaci::PlanStatus::kGoalOffMap:
    case eaci::PlanStatus::kGoalBlocked:
    case eaci::PlanStatus::kInvalidParameters:
    case eaci::PlanStatus::kInvalidMap: return kExitBadInput;
  }
  return kExitBadInput;
}

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void onInterrupt(int) { g_interrupted = 1; }

// A message on one line, never empty.
std::string errorLine(const std::string& message) {
  const std::string line = eaci::oneLine(message);
  return line.empty() ? "unknown error" : line;
}

void printError(const std::string& message) { std::cerr << kErrorPrefix << errorLine(message) << std::endl; }

struct Options {
  std::string map_path;
  std::string start_rc, start_cell, start_xy;
  std::string goal_rc, goal_cell, goal_xy;
  std::string algorithm = "eaci";
  std::string seed;
  std::string turn_cost;  // = --set turn_cost=...
  double start_yaw_deg = std::numeric_limits<double>::quiet_NaN();  // --start-yaw: degrees, NaN = none
  double goal_yaw_deg = std::numeric_limits<double>::quiet_NaN();   // --goal-yaw
  std::string params_file;
  std::vector<std::string> sets;
  std::string json_file;
  std::string png_file;
  std::string unknown;  // expensive (or its old name free) | obstacle: --set allow_unknown=true | false
  std::string tolerance;           // m: the route ends on the cell nearest the goal within it that the start can reach
  std::string inflate;             // m: inflation radius (costmap_2d's inflation)
  std::string inscribed_radius;    // m, with --inflate
  std::string cost_scaling_factor; // 1/m, with --inflate
  bool quiet = false;
};

// A flat YAML mapping of parameter names to scalar values, applied on top of `p`.
void applyParameterFile(eaci::Parameters& p, const std::string& file) {
  try {
    eaci::applyParameterFile(file, p, "--params '" + file + "'");
  } catch (const eaci::ParameterFileError& e) {
    throw InputError(e.what(), eaci::PlanStatus::kInvalidParameters);
  }
}

// Paper defaults, then --params, then each --set in order, then --unknown, --seed and
// --turn-cost; validated.
void buildParameters(const Options& o, eaci::Parameters& p) {
  if (!o.params_file.empty()) applyParameterFile(p, o.params_file);
  for (const std::string& assignment : o.sets) {
    std::pair<std::string, std::string> kv;
    try {
      kv = eaci::cli::splitAssignment(assignment, "--set");
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
    try {
      eaci::setParameter(p, kv.first, kv.second);
    } catch (const eaci::ParameterError& e) {
      throw InputError(std::string("--set ") + assignment + ": " + e.what(), eaci::PlanStatus::kInvalidParameters);
    }
  }
  if (!o.unknown.empty()) p.allow_unknown = o.unknown != "obstacle";
  if (!o.seed.empty()) {
    try {
      eaci::setParameter(p, "seed", o.seed);
    } catch (const eaci::ParameterError& e) {
      throw InputError(std::string("--") + e.what(), eaci::PlanStatus::kInvalidParameters);  // "--seed: 'x' is not an integer"
    }
  }
  if (!o.turn_cost.empty()) {
    try {
      eaci::setParameter(p, "turn_cost", o.turn_cost);
    } catch (const eaci::ParameterError& e) {
      throw InputError(std::string("--turn-cost: ") + e.what(), eaci::PlanStatus::kInvalidParameters);
    }
  }
  const std::string error = eaci::validationError(p);
  if (!error.empty()) throw InputError("invalid parameter: " + error, eaci::PlanStatus::kInvalidParameters);
}

// One of R,C / serial / X,Y (exactly one is set; checked before).
eaci::Cell resolveEndpoint(const eaci::OccupancyMap& map, const std::string& rc, const std::string& serial,
                           const std::string& xy, const std::string& name) {
  try {
    if (!rc.empty()) return eaci::cli::parseRowCol(rc, "--" + name);
    if (!serial.empty()) {
      const std::int64_t g = eaci::cli::parseSerial(serial, "--" + name + "-cell");
      const std::int64_t count = static_cast<std::int64_t>(map.width) * map.height;
      if (g < 1 || g > count)
        throw InputError("--" + name + "-cell " + std::to_string(g) + " is off the map: serial numbers run 1.." +
                         std::to_string(count) + " on this " + std::to_string(map.width) + " x " +
                         std::to_string(map.height) + " map",
                         name == "start" ? eaci::PlanStatus::kStartOffMap : eaci::PlanStatus::kGoalOffMap);
      return eaci::cellFromSerial(g, map.width);
    }
    const auto [x, y] = eaci::cli::parseXY(xy, "--" + name + "-xy");
    const std::optional<eaci::Cell> cell = map.worldToCell({x, y});
    if (!cell) {
      const double x1 = map.origin.x() + map.width * map.resolution, y1 = map.origin.y() + map.height * map.resolution;
      throw InputError("--" + name + "-xy " + xy + " is off the map (x " + formatNumber(map.origin.x()) + " .. " +
                       formatNumber(x1) + " m, y " + formatNumber(map.origin.y()) + " .. " + formatNumber(y1) + " m)",
                       name == "start" ? eaci::PlanStatus::kStartOffMap : eaci::PlanStatus::kGoalOffMap);
    }
    return *cell;
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

std::string describeCell(const eaci::OccupancyMap& map, eaci::Cell c) {
  const Eigen::Vector2d p = map.cellToWorld(c);
  return "(row " + std::to_string(c.row) + ", col " + std::to_string(c.col) + ") = (" + formatNumber(p.x()) + ", " +
         formatNumber(p.y()) + ") m";
}

std::string upper(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

std::string baseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The map as the parameters read it: unknown cells per allow_unknown, and in a map of costs
// (mode: raw) obstacles from lethal_cost up.
eaci::GridView mapView(const eaci::OccupancyMap& map, const eaci::Parameters& params) {
  return map.view(params.allow_unknown ? eaci::UnknownPolicy::kExpensive : eaci::UnknownPolicy::kObstacle,
                  static_cast<std::uint8_t>(params.lethal_cost));
}

// Free cells of the original map that EACI's auxiliary map (Eq. 12) blocks.
std::vector<std::uint8_t> auxiliaryBlocked(const eaci::OccupancyMap& map, const eaci::Parameters& params,
                                           eaci::Cell start, eaci::Cell goal) {
  const eaci::CostGrid grid = eaci::CostGrid::fromView(mapView(map, params), params.allow_corner_cutting);
  const eaci::CostGrid aux = eaci::auxiliaryMap(grid, start, goal);
  std::vector<std::uint8_t> blocked(grid.cellCount(), 0);
  for (std::size_t i = 0; i < blocked.size(); ++i) {
    const eaci::Cell c = grid.cellAt(i);
    blocked[i] = aux.isBlocked(c) && !grid.isBlocked(c) ? 1 : 0;
  }
  return blocked;
}

// --inflate, --inscribed-radius, --cost-scaling-factor; none if --inflate is not given.
std::optional<eaci::InflationParameters> inflationOf(const Options& o) {
  try {
    if (o.inflate.empty()) {
      if (!o.inscribed_radius.empty()) throw InputError("--inscribed-radius needs --inflate RADIUS");
      if (!o.cost_scaling_factor.empty()) throw InputError("--cost-scaling-factor needs --inflate RADIUS");
      return std::nullopt;
    }
    eaci::InflationParameters p;
    p.inflation_radius = eaci::cli::parseNonNegative(o.inflate, "--inflate");
    if (!o.inscribed_radius.empty()) p.inscribed_radius = eaci::cli::parseNonNegative(o.inscribed_radius, "--inscribed-radius");
    if (!o.cost_scaling_factor.empty())
      p.cost_scaling_factor = eaci::cli::parseNonNegative(o.cost_scaling_factor, "--cost-scaling-factor");
    if (p.inscribed_radius > p.inflation_radius)
      throw InputError("--inscribed-radius " + formatNumber(p.inscribed_radius) + " m exceeds --inflate " +
                       formatNumber(p.inflation_radius) + " m");
    const std::string error = eaci::inflationError(p);
    if (!error.empty()) throw InputError("--inflate: " + error);
    return p;
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

std::string imageCaption(const eaci::PlanResult& r, const eaci::tools::PlanContext& context) {
  std::ostringstream s;
  s << (r.algorithm == eaci::Algorithm::kAStar ? std::string("A*") : upper(eaci::toString(r.algorithm)));
  if (r.algorithm == eaci::Algorithm::kMaaco) s << " (re-implemented from public descriptions, not the authors' code)";
  s << " on " << baseName(context.map_path);
  if (r.success()) {
    s << ", seed " << context.parameters.seed;
    if (r.algorithm != eaci::Algorithm::kAStar)
      s << ": converged at iteration " << r.iterations_to_converge << " of " << r.iterations_run << ", "
        << r.lost_ants_total << " lost ants";
    if (r.islands.size() > 2) s << ", " << r.islands.size() - 2 << " islands";
    for (const std::string& line :
         eaci::tools::routeCaptionLines(r, context.map ? context.map->resolution : 1.0, context.parameters.smooth_path))
      s << "\n" << line;
  } else {
    s << ": " << errorLine(r.error);
  }
  return s.str();
}

struct Outputs {
  std::string json_error;
  std::string png_error;
};

// Writes the JSON report and the picture where asked; errors are returned, not thrown.
Outputs writeOutputs(const Options& o, const eaci::PlanResult& r, const eaci::tools::PlanContext& context,
                     eaci::UnknownPolicy unknown, const eaci::Parameters& params) {
  Outputs out;
  if (!o.json_file.empty()) {
    try {
      eaci::tools::writePlanJson(o.json_file, r, context);
    } catch (const std::exception& e) {
      out.json_error = e.what();
    }
  }
  if (!o.png_file.empty() && context.map) {
    try {
      eaci::tools::PlanDrawing drawing;
      drawing.map = context.map;
      drawing.unknown = unknown;
      drawing.lethal_cost = static_cast<std::uint8_t>(params.lethal_cost);
      drawing.result = &r;
      drawing.start = context.start;
      drawing.goal = context.goal;
      const auto on_free = [&](const std::optional<eaci::Cell>& c) {
        return c && mapView(*context.map, params).isFree(*c);
      };
      if (r.algorithm == eaci::Algorithm::kEaci && on_free(context.start) && on_free(context.goal))
        drawing.auxiliary_blocked = auxiliaryBlocked(*context.map, params, *context.start, *context.goal);
      drawing.caption = imageCaption(r, context);
      drawing.planned_on = context.planned_on;
      drawing.smoothed = params.smooth_path;
      eaci::tools::writePng(o.png_file, eaci::tools::renderPlan(drawing).image);
    } catch (const std::exception& e) {
      out.png_error = e.what();
    }
  } else if (!o.png_file.empty()) {
    out.png_error = "cannot write PNG '" + o.png_file + "': no map";
  }
  return out;
}

void printSummary(const Options& o, const eaci::PlanResult& r, const eaci::tools::PlanContext& context) {
  const eaci::OccupancyMap& map = *context.map;
  const double res = map.resolution;
  std::ostringstream s;
  s << "algorithm:      " << eaci::toString(r.algorithm) << "\n";
  s << "map:            " << context.map_path << " (" << map.width << " x " << map.height << " cells, "
    << formatNumber(res) << " m/cell, "
    << (map.values == eaci::CellValues::kCostmapCosts
            ? "costmap costs, obstacles from " + std::to_string(context.parameters.lethal_cost) + ", "
            : std::string())
    << "unknown cells as " << context.unknown_policy << ")\n";
  s << "start:          " << describeCell(map, *context.start) << "\n";
  s << "goal:           " << describeCell(map, *context.goal);
  if (context.requested_goal) s << " (moved from " << describeCell(map, *context.requested_goal) << " by --tolerance)";
  s << "\n";
  // The route the search found, cell to neighbouring cell, and the one a robot drives.
  s << "grid route:     length " << formatNumber(r.length) << " cells = " << formatNumber(r.length * res)
    << " m, total turn " << formatNumber(r.total_turn_deg, 1) << " deg (" << r.path.size() << " cells, 8-connected)\n";
  if (context.parameters.turn_cost > 0) {
    const double end_turn_deg = eaci::endTurnRadians(r.path, context.end_headings) * 180.0 / M_PI;
    s << "combined cost:  " << formatNumber(r.combined_cost) << " = cost " << formatNumber(r.cost) << " + turn price "
      << formatNumber(r.turn_price) << " x " << formatNumber(r.total_turn_deg + end_turn_deg, 1) << " deg in radians";
    if (context.parameters.turn_cost_unit == eaci::TurnCostUnit::kRouteCell)
      s << " (turn_cost " << formatNumber(context.parameters.turn_cost) << " x the cheapest route's average cell, "
        << formatNumber(r.turn_price / context.parameters.turn_cost) << ")";
    if (context.end_headings.hasStart() || context.end_headings.hasGoal())
      s << " (" << formatNumber(end_turn_deg, 1) << " of them onto the route and off it, --start-yaw/--goal-yaw)";
    s << "\n";
  }
  if (context.parameters.smooth_path)
    s << "smoothed route: length " << formatNumber(r.smoothed_length) << " cells = " << formatNumber(r.smoothed_length * res)
      << " m, total turn " << formatNumber(eaci::totalTurnDegrees(r.smoothed_path), 1) << " deg ("
      << r.smoothed_path.size() << " corners joined by straight lines: what a robot drives)\n";
  else
    s << "smoothed route: off (--set smooth_path=true smooths the grid route into one a robot drives)\n";
  if (r.algorithm != eaci::Algorithm::kAStar) {
    s << "iterations:     converged at " << r.iterations_to_converge << " of " << r.iterations_run << " run";
    if (r.stopped_early) s << " (stopped early)";
    if (r.interrupted) s << (r.route_from_search ? " (interrupted before any ant arrived: A*'s route)" : " (interrupted)");
    s << "\n";
    s << "lost ants:      " << r.lost_ants_total << " in total\n";
  }
  const std::size_t inner = r.islands.size() >= 2 ? r.islands.size() - 2 : 0;
  s << "islands:        " << inner << " between start and goal (" << r.islands.size() << " waypoints)\n";
  s << "seed:           " << context.parameters.seed << "\n";
  s << "time:           " << formatNumber(context.time_ms.value_or(0.0), context.time_ms.value_or(0.0) < 10 ? 3 : 1) << " ms\n";
  if (!o.json_file.empty()) s << "json:           " << o.json_file << "\n";
  if (!o.png_file.empty()) s << "png:            " << o.png_file << "\n";
  std::cout << s.str() << std::flush;
}

int run(int argc, char** argv) {
  Options o;
  CLI::App app{"Plan a route on an occupancy map with EACI (Li, Li & Cui 2025), classic ACO, MAACO\n"
               "(re-implemented from public descriptions, not the authors' code) or A*.\n"
               "Exit status: 0 path found; 2 bad input (arguments, map, parameters, start or goal off the map or\n"
               "in an obstacle); 3 no path; 4 stopped (SIGINT/SIGTERM) before a path was found. The JSON's\n"
               "\"outcome\" names it: ok, no_path, stopped, start_off_map, start_blocked, goal_off_map,\n"
               "goal_blocked, invalid_parameters, invalid_map, bad_input.",
               "eaci_plan"};
  app.option_defaults()->always_capture_default();
  app.add_option("--map", o.map_path, "map: .yaml (map_server), .map (MovingAI benchmark map) or .txt (0/1 matrix, first line = top row)")
      ->required();
  auto* start_rc = app.add_option("--start", o.start_rc, "start cell ROW,COL (0-based, row 0 = top)");
  auto* start_cell = app.add_option("--start-cell", o.start_cell, "start cell by the paper's serial number 1..W*H");
  auto* start_xy = app.add_option("--start-xy", o.start_xy, "start point X,Y in map-frame metres");
  auto* goal_rc = app.add_option("--goal", o.goal_rc, "goal cell ROW,COL (0-based, row 0 = top)");
  auto* goal_cell = app.add_option("--goal-cell", o.goal_cell, "goal cell by the paper's serial number 1..W*H");
  auto* goal_xy = app.add_option("--goal-xy", o.goal_xy, "goal point X,Y in map-frame metres");
  for (const auto& group : {std::vector<CLI::Option*>{start_rc, start_cell, start_xy},
                      std::vector<CLI::Option*>{goal_rc, goal_cell, goal_xy}}) {
    for (auto* a : group)
      for (auto* b : group)
        if (a != b) a->excludes(b);
  }
  app.add_option("--algorithm", o.algorithm, "eaci, aco (classic ant colony), maaco (re-implemented from public descriptions, not the authors' code) or astar")
      ->check(CLI::IsMember({"eaci", "aco", "maaco", "astar"}));
  app.add_option("--seed", o.seed, "random seed (overrides --params and --set)");
  app.add_option("--turn-cost", o.turn_cost,
                 "the cost of one radian of heading change between consecutive moves, added to a route's cost "
                 "(= --set turn_cost=..., overrides --params and --set; default 0); every algorithm then minimises "
                 "cost + turn_cost x turn, astar exactly");
  app.add_option("--start-yaw", o.start_yaw_deg,
                 "degrees counter-clockwise from east (+x; 90 = north, up the map): the way the robot faces at the "
                 "start; with --turn-cost the turn onto the first move is priced like a corner (default: none)")
      ->check(CLI::Range(-360.0, 360.0));
  app.add_option("--goal-yaw", o.goal_yaw_deg,
                 "degrees, as --start-yaw: the way the robot must face at the goal; with --turn-cost the turn off "
                 "the last move onto it is priced (default: none)")
      ->check(CLI::Range(-360.0, 360.0));
  app.add_option("--params", o.params_file, "flat YAML mapping of parameter names to values");
  app.add_option("--set", o.sets, "set one parameter, key=value (repeatable, applied in order after --params)")
      ->allow_extra_args(false);
  app.add_option("--unknown", o.unknown,
                 "how unknown map cells count: obstacle, or expensive: passable at the dearest cost (252 on the "
                 "costmap scale), so routes cross unknown space only where a detour costs more; free is the old "
                 "word for expensive (= --set allow_unknown=false|true; default obstacle)")
      ->check(CLI::IsMember({"expensive", "free", "obstacle"}));
  app.add_option("--tolerance", o.tolerance,
                 "metres: the route ends on the cell nearest the goal within this that the start can reach (a goal "
                 "in an obstacle, or walled off from the start, moves there)");
  app.add_option("--inflate", o.inflate,
                 "inflation radius in metres: obstacles spread costmap_2d's inflation cost, routes keep off walls");
  app.add_option("--inscribed-radius", o.inscribed_radius, "metres, with --inflate: cells this near an obstacle are "
                 "obstacles too (default 0)");
  app.add_option("--cost-scaling-factor", o.cost_scaling_factor,
                 "with --inflate: how fast the inflation cost decays with the distance, 1/m (default 10)");
  app.add_option("--json", o.json_file, "write a JSON report here (also on failure)");
  app.add_option("--png", o.png_file, "write a PNG picture of the map, pheromone, islands and path here");
  app.add_flag("--quiet,-q", o.quiet, "print nothing on success");
  app.footer("Parameters: " + [] {
    std::string names;
    for (const std::string& n : eaci::parameterNames()) names += (names.empty() ? "" : ", ") + n;
    return names;
  }());

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    printError(e.what());
    return kExitBadInput;
  }

  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;
  eaci::parseAlgorithm(o.algorithm, algorithm);
  eaci::UnknownPolicy unknown = eaci::UnknownPolicy::kObstacle;  // params.allow_unknown, once read

  std::optional<eaci::OccupancyMap> map;
  eaci::tools::PlanContext context;
  context.map_path = o.map_path;
  context.unknown_policy = "obstacle";
  eaci::Parameters params{};
  std::vector<std::uint8_t> inflated;  // the map's costmap_2d costs with --inflate
  eaci::GridView planning_view;        // what the planners read: the map, or `inflated`

  // Any failure before plan(): report it in the JSON (as far as known, with its outcome word) and exit 2.
  auto fail = [&](const std::string& message, std::optional<eaci::PlanStatus> status) {
    context.map = map ? &*map : nullptr;
    context.bad_input = !status;
    context.parameters = params;
    eaci::PlanResult failed;
    failed.algorithm = algorithm;
    failed.status = status.value_or(eaci::PlanStatus::kInvalidParameters);  // not written with bad_input
    failed.error = errorLine(message);
    writeOutputs(o, failed, context, unknown, params);
    printError(message);
    return kExitBadInput;
  };

  try {
    const int starts = int(!o.start_rc.empty()) + int(!o.start_cell.empty()) + int(!o.start_xy.empty());
    const int goals = int(!o.goal_rc.empty()) + int(!o.goal_cell.empty()) + int(!o.goal_xy.empty());
    if (starts != 1) throw InputError("give the start once: --start ROW,COL, --start-cell N or --start-xy X,Y");
    if (goals != 1) throw InputError("give the goal once: --goal ROW,COL, --goal-cell N or --goal-xy X,Y");
    buildParameters(o, params);
    unknown = params.allow_unknown ? eaci::UnknownPolicy::kExpensive : eaci::UnknownPolicy::kObstacle;
    context.unknown_policy = params.allow_unknown ? "expensive" : "obstacle";
    map = eaci::loadMap(o.map_path);
    context.map = &*map;
    context.start = resolveEndpoint(*map, o.start_rc, o.start_cell, o.start_xy, "start");
    context.goal = resolveEndpoint(*map, o.goal_rc, o.goal_cell, o.goal_xy, "goal");
    planning_view = mapView(*map, params);
    if (const auto inflation = inflationOf(o)) {
      inflated = eaci::inflatedCosts(planning_view, map->resolution, *inflation);
      planning_view = eaci::GridView(inflated.data(), map->width, map->height, eaci::RowOrder::kTopFirst,
                                     eaci::inflatedCostsInterpretation(params.allow_unknown));
      context.planned_on = planning_view;
    }
    if (!o.tolerance.empty()) {
      double tolerance = 0;
      try {
        tolerance = eaci::cli::parseNonNegative(o.tolerance, "--tolerance");
      } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
      }
      const double cells = tolerance / map->resolution;
      const std::optional<eaci::Cell> free = eaci::nearestFreeCell(planning_view, *context.goal, cells);
      if (!free)
        throw InputError("goal " + describeCell(*map, *context.goal) + " is not on free space and no free cell lies within --tolerance " +
                         formatNumber(tolerance) + " m (" + formatNumber(cells, 2) + " cells) of it",
                         eaci::PlanStatus::kGoalBlocked);
      // As the planning service does it (navfn's rule): the cell nearest the goal within the
      // tolerance that the start can reach, so a replay of a move_base plan ends where it did.
      std::optional<eaci::Cell> target = free;
      if (cells >= 1 && planning_view.isFree(*context.start)) {
        const eaci::CostGrid grid = eaci::CostGrid::fromView(planning_view, params.allow_corner_cutting);
        if (const auto reachable = eaci::nearestReachableCell(grid, *context.start, *context.goal, cells)) target = reachable;
      }
      if (*target != *context.goal) {
        context.requested_goal = context.goal;
        context.goal = target;
      }
    }
  } catch (const InputError& e) {
    return fail(e.what(), e.status());
  } catch (const eaci::MapLoadError& e) {
    return fail(e.what(), eaci::PlanStatus::kInvalidMap);
  } catch (const eaci::ParameterError& e) {
    return fail(std::string("invalid parameter: ") + e.what(), eaci::PlanStatus::kInvalidParameters);
  } catch (const YAML::Exception& e) {
    return fail(e.what(), std::nullopt);
  }
  context.parameters = params;

  eaci::PlanOptions options;
  options.record_pheromone = !o.png_file.empty() && algorithm != eaci::Algorithm::kAStar;
  options.should_stop = [](int) { return g_interrupted != 0; };
  options.end_headings = {o.start_yaw_deg * M_PI / 180.0, o.goal_yaw_deg * M_PI / 180.0};  // NaN: none
  context.end_headings = options.end_headings;
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  const auto t0 = std::chrono::steady_clock::now();
  const eaci::PlanResult result = eaci::plan(planning_view, *context.start, *context.goal, algorithm, params, options);
  const auto t1 = std::chrono::steady_clock::now();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  context.time_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();

  const Outputs written = writeOutputs(o, result, context, unknown, params);
  if (!result.success()) {
    printError(result.error.empty() ? "planning failed" : result.error);
    return exitCodeOf(result.status);
  }
  if (!written.json_error.empty()) {
    printError(written.json_error);
    return kExitBadInput;
  }
  if (!written.png_error.empty()) {
    printError(written.png_error);
    return kExitBadInput;
  }
  if (!o.quiet) printSummary(o, result, context);
  return kExitPath;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const eaci::MapLoadError& e) {
    printError(e.what());
  } catch (const eaci::ParameterError& e) {
    printError(std::string("invalid parameter: ") + e.what());
  } catch (const YAML::Exception& e) {
    printError(e.what());
  } catch (const std::bad_alloc&) {
    printError("out of memory");
  } catch (const std::exception& e) {
    printError(e.what());
  } catch (...) {
    printError("unexpected failure");
  }
  return kExitBadInput;
}
