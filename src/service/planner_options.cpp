#include "planner_options.hpp"

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
          if (!eaci::parseAlgorithm(v, o.algorithm))
            throw eaci::ParameterError("algorithm must be eaci, aco, maaco or astar (got '" + v + "')");
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
      {"route_hysteresis", fieldAccess<Options>("route_hysteresis", &Options::route_hysteresis)},
      {"price_goal_heading", fieldAccess<Options>("price_goal_heading", &Options::price_goal_heading)},
      {"run_past_goal", fieldAccess<Options>("run_past_goal", &Options::run_past_goal)},
      {"lead_start_turn", fieldAccess<Options>("lead_start_turn", &Options::lead_start_turn)},
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
  params.smooth_path = true;    // robots drive the smoothed route
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

std::vector<std::string> rosParameterNames() {
  std::vector<std::string> names = eaci::parameterNames();
  for (const auto& entry : optionTable()) names.push_back(entry.first);
  return names;
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
  else if (!std::isfinite(options.max_planning_time) || options.max_planning_time < 0)
    e << "max_planning_time must be >= 0 seconds, 0 = no limit (got " << options.max_planning_time << ")";
  else if (options.landmarks < 0 || options.landmarks > 64)
    e << "landmarks must be in 0..64, 0 = none (got " << options.landmarks << ")";
  else if (!std::isfinite(options.route_hysteresis) || options.route_hysteresis < 0 || options.route_hysteresis > 1)
    e << "route_hysteresis must be in [0, 1], the fraction by which a replan's route must be cheaper than the "
         "route sent last to replace it, 0 = off (got " << options.route_hysteresis << ")";
  else if (!std::isfinite(options.run_past_goal) || options.run_past_goal < 0 || options.run_past_goal > 0.5)
    e << "run_past_goal must be in [0, 0.5] m, how far the plan runs on past the goal before it ends there, "
         "0 = off (got " << options.run_past_goal << ")";
  else if (!std::isfinite(options.lead_start_turn) || options.lead_start_turn < 0 || options.lead_start_turn > 0.5)
    e << "lead_start_turn must be in [0, 0.5] m, the radius of the arc a plan that leaves behind the robot "
         "begins with (dwa_local_planner's forward_point_distance), 0 = off (got " << options.lead_start_turn << ")";
  return e.str();
}

}  // namespace eaci_service
