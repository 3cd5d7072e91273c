#include "planner_options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

namespace eaci_service {
namespace {

using Options = RosPlannerOptions;

// The ROS options by name, rows of the same kind as the core's table (eaci::detail::fieldAccess).
const std::map<std::string, eaci::detail::FieldAccess<Options>>& optionTable() {
  using eaci::ParameterValue;
  using eaci::detail::fieldAccess;
  static const std::map<std::string, eaci::detail::FieldAccess<Options>> table = {
      {"algorithm",
       {[](Options& o, const std::string& v) {
          eaci::Algorithm algorithm = eaci::Algorithm::kEaci;
          if (!eaci::parseAlgorithm(v, algorithm) ||
              (algorithm != eaci::Algorithm::kEaci && algorithm != eaci::Algorithm::kAStar))
            throw eaci::ParameterError("algorithm must be eaci or astar (got '" + v +
                                       "'; the paper's aco and maaco baselines run in eaci_plan and eaci_bench)");
          o.algorithm = algorithm;
        },
        [](const Options& o) { return ParameterValue{std::string(eaci::toString(o.algorithm))}; }}},
      {"default_tolerance", fieldAccess<Options>("default_tolerance", &Options::default_tolerance)},
      {"occupied_threshold", fieldAccess<Options>("occupied_threshold", &Options::occupied_threshold)},
      {"publish_plan", fieldAccess<Options>("publish_plan", &Options::publish_plan)},
      {"max_planning_time", fieldAccess<Options>("max_planning_time", &Options::max_planning_time)},
      {"visualize_pheromone", fieldAccess<Options>("visualize_pheromone", &Options::visualize_pheromone)},
      {"robot_radius", fieldAccess<Options>("robot_radius", &Options::robot_radius)},
      {"inflation_radius", fieldAccess<Options>("inflation_radius", &Options::inflation_radius)},
      {"cost_scaling_factor", fieldAccess<Options>("cost_scaling_factor", &Options::cost_scaling_factor)},
      {"landmarks", fieldAccess<Options>("landmarks", &Options::landmarks)},
      {"orientation_mode",
       {[](Options& o, const std::string& v) {
          try {
            o.orientation_mode = eaci::orientationModeFromString(v);
          } catch (const std::invalid_argument& e) {
            throw eaci::ParameterError("orientation_mode: " + std::string(e.what()));
          }
        },
        [](const Options& o) { return ParameterValue{std::int64_t{static_cast<int>(o.orientation_mode)}}; }}},
  };
  return table;
}

}  // namespace

eaci::Parameters rosDefaultParameters() {
  eaci::Parameters params;
  params.allow_unknown = true;  // the ROS default, as navfn and global_planner
  params.cost_factor = 0.8;     // navfn's weighting of the costmap (50 + 0.8 c a cell): its doors, its route lengths
  params.smooth_path = true;    // robots drive the smoothed route,
  params.round_corners = 2;     // its corners cut in two passes (a 90-degree bend becomes two of about 45),
  params.smooth_tolerance = 0.1;  // each cut through cells at most 10 % costlier than the corner it cuts off
                                  // (and never nearer an obstacle than it: path/smoothing.hpp)
  params.early_stop_iterations = 10;
  params.stop_gap = 0.01;
  params.region_margin = 4;
  return params;
}

std::string robotDefaultsSummary() {
  const auto paper = eaci::parameterValues(eaci::Parameters{});
  const auto robot = eaci::parameterValues(rosDefaultParameters());
  std::string summary;
  for (std::size_t i = 0; i < robot.size(); ++i)  // the same names in the same order
    if (robot[i].second != paper[i].second)
      summary += (summary.empty() ? "" : ", ") + robot[i].first + " " + valueText(robot[i].second);
  return summary;
}

const std::vector<std::string>& robotParameterNames() {
  static const std::vector<std::string> names = {
      "algorithm",    "default_tolerance", "allow_unknown", "neutral_cost", "cost_factor",  "lethal_cost",
      "turn_cost",    "smooth_path",       "max_planning_time", "orientation_mode", "publish_plan",
      "visualize_pheromone"};
  return names;
}

const std::vector<std::string>& colonyParameterNames() {
  static const std::vector<std::string> names = {
      "ants",    "max_iterations", "alpha",          "beta",          "q",
      "kappa",   "islands",        "lambda",         "epsilon",       "island_strategy",
      "island_spacing_max", "region_margin", "early_stop_iterations", "stop_gap", "seed", "threads"};
  return names;
}

std::vector<std::string> rosParameterNames() {
  std::vector<std::string> names = robotParameterNames();
  names.insert(names.end(), colonyParameterNames().begin(), colonyParameterNames().end());
  for (const char* at_start : {"occupied_threshold", "robot_radius", "inflation_radius", "cost_scaling_factor", "landmarks"})
    names.emplace_back(at_start);
  return names;
}

namespace {

const std::map<std::string, std::string>& droppedOptions() {
  static const std::map<std::string, std::string> dropped = {
      {"route_hysteresis", "dropped: it bought no arrival time in any drive"},
      {"price_goal_heading", "dropped: with turn_cost > 0 the turn onto the goal's heading is always priced"},
      {"run_past_goal", "dropped: a controller's approach to the goal is the controller's to tune"},
      {"lead_start_turn", "dropped: which way a controller turns is the controller's to tune"},
      {"centre_gaps", "dropped: it moved one door's clearance by millimetres"},
      {"way_cost_factor", "dropped: it moved one goal of one map"},
      {"way_corridor", "dropped with way_cost_factor"},
  };
  return dropped;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> unreadParameters() {
  std::vector<std::pair<std::string, std::string>> unread(droppedOptions().begin(), droppedOptions().end());
  const auto ros = rosParameterNames();
  for (const std::string& name : eaci::parameterNames()) {
    if (std::find(ros.begin(), ros.end(), name) != ros.end()) continue;
    unread.emplace_back(name, name == "allow_corner_cutting" ? "a robot never cuts corners (the paper's benchmarks only)"
                              : name == "round_corners" || name == "smooth_tolerance"
                                  ? "fixed on a robot (round_corners 2, smooth_tolerance 0.1): the command-line planner's"
                                  : "a parameter of the command-line planner and the benchmarks only");
  }
  return unread;
}

void setRosParameter(eaci::Parameters& params, RosPlannerOptions& options, const std::string& name,
                     const std::string& text) {
  const auto option = optionTable().find(name);
  if (option != optionTable().end()) option->second.set(options, text);
  else eaci::setParameter(params, name, text);
}

eaci::ParameterValue rosParameterValue(const eaci::Parameters& params, const RosPlannerOptions& options,
                                       const std::string& name) {
  const auto option = optionTable().find(name);
  if (option != optionTable().end()) return option->second.get(options);
  const auto& table = eaci::detail::parameterTable();
  const auto parameter = table.find(name);
  if (parameter == table.end()) throw eaci::ParameterError("unknown parameter '" + name + "'");
  return parameter->second.get(params);
}

std::string valueText(const eaci::ParameterValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::string>) return v;
        else {  // the shortest text that reads back exactly
          char text[32];
          return std::string(text, std::to_chars(text, text + sizeof(text), v).ptr);
        }
      },
      value);
}

std::string rosValidationError(const eaci::Parameters& params, const RosPlannerOptions& options) {
  std::string error = eaci::validationError(params);
  if (!error.empty()) return error;
  std::ostringstream e;
  if (!std::isfinite(options.default_tolerance) || options.default_tolerance < 0)
    e << "default_tolerance must be a distance >= 0 (got " << options.default_tolerance << ")";
  else if (options.occupied_threshold < 1 || options.occupied_threshold > 100)
    e << "occupied_threshold must be in 1..100 (got " << options.occupied_threshold << ")";
  else if (!std::isfinite(options.robot_radius) || options.robot_radius < 0)
    e << "robot_radius must be a distance >= 0 (got " << options.robot_radius << ")";
  else if (!std::isfinite(options.inflation_radius) || options.inflation_radius < 0)
    e << "inflation_radius must be a distance >= 0 (got " << options.inflation_radius << ")";
  else if (options.inflation_radius > 0 && options.robot_radius > options.inflation_radius)
    e << "inflation_radius must be at least robot_radius (got " << options.inflation_radius << " < "
      << options.robot_radius << ")";
  else if (!std::isfinite(options.cost_scaling_factor) || options.cost_scaling_factor < 0)
    e << "cost_scaling_factor must be >= 0 (got " << options.cost_scaling_factor << ")";
  else if (!std::isfinite(options.max_planning_time) || options.max_planning_time < 0 ||
           options.max_planning_time > kMaxPlanningTime)
    e << "max_planning_time must be in [0, " << kMaxPlanningTime << "] seconds, 0 = no limit (got "
      << options.max_planning_time << ")";
  else if (options.landmarks < 0 || options.landmarks > 64)
    e << "landmarks must be in 0..64, 0 = none (got " << options.landmarks << ")";
  return e.str();
}

}  // namespace eaci_service
