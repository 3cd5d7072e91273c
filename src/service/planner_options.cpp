#include "planner_options.hpp"

#include <cmath>
#include <sstream>
#include <type_traits>
#include <variant>

namespace eaci_ros {
namespace {

std::string exactText(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

std::string boolText(bool value) { return value ? "true" : "false"; }

}  // namespace

eaci::Parameters rosDefaultParameters() {
  eaci::Parameters params;
  params.allow_unknown = true;  // the ROS default, as navfn and global_planner
  params.smooth_path = true;    // robots drive the smoothed route
  params.early_stop_iterations = 10;
  params.stop_gap = 0.01;
  params.threads = 0;
  params.region_margin = 4;
  return params;
}

std::string robotDefaultsSummary() {
  const eaci::Parameters paper;
  const eaci::Parameters robot = rosDefaultParameters();
  const RosPlannerOptions options;
  std::string summary;
  const auto paper_values = eaci::parameterValues(paper);
  for (const auto& [name, value] : eaci::parameterValues(robot)) {
    for (const auto& [paper_name, paper_value] : paper_values) {
      if (paper_name != name || paper_value == value) continue;
      if (!summary.empty()) summary += ", ";
      summary += name + " " + rosParameterText(robot, options, name);
    }
  }
  return summary;
}

const std::vector<std::string>& rosOptionNames() {
  static const std::vector<std::string> names = {"algorithm",          "default_tolerance", "occupied_threshold",
                                                 "publish_plan",       "max_planning_time", "visualize_pheromone",
                                                 "robot_radius",       "orientation_mode",  "inflation_radius",
                                                 "cost_scaling_factor", "landmarks"};
  return names;
}

void setRosParameter(eaci::Parameters& params, RosPlannerOptions& options, const std::string& name,
                     const std::string& text) {
  if (name == "algorithm") {
    if (!eaci::parseAlgorithm(text, options.algorithm))
      throw eaci::ParameterError("algorithm must be eaci, aco or astar (got '" + text + "')");
  } else if (name == "default_tolerance") {
    options.default_tolerance = eaci::parseDouble(name, text);
  } else if (name == "occupied_threshold") {
    options.occupied_threshold = eaci::parseInt(name, text);
  } else if (name == "publish_plan") {
    options.publish_plan = eaci::parseBool(name, text);
  } else if (name == "max_planning_time") {
    options.max_planning_time = eaci::parseDouble(name, text);
  } else if (name == "visualize_pheromone") {
    options.visualize_pheromone = eaci::parseBool(name, text);
  } else if (name == "robot_radius") {
    options.robot_radius = eaci::parseDouble(name, text);
  } else if (name == "inflation_radius") {
    options.inflation_radius = eaci::parseDouble(name, text);
  } else if (name == "cost_scaling_factor") {
    options.cost_scaling_factor = eaci::parseDouble(name, text);
  } else if (name == "landmarks") {
    options.landmarks = eaci::parseInt(name, text);
  } else if (name == "orientation_mode") {
    try {
      options.orientation_mode = eaci::orientationModeFromString(text);
    } catch (const std::invalid_argument& e) {
      throw eaci::ParameterError("orientation_mode: " + std::string(e.what()));
    }
  } else {
    eaci::setParameter(params, name, text);
  }
}

std::string rosParameterText(const eaci::Parameters& params, const RosPlannerOptions& options, const std::string& name) {
  if (name == "algorithm") return eaci::toString(options.algorithm);
  if (name == "default_tolerance") return exactText(options.default_tolerance);
  if (name == "occupied_threshold") return std::to_string(options.occupied_threshold);
  if (name == "publish_plan") return boolText(options.publish_plan);
  if (name == "max_planning_time") return exactText(options.max_planning_time);
  if (name == "visualize_pheromone") return boolText(options.visualize_pheromone);
  if (name == "robot_radius") return exactText(options.robot_radius);
  if (name == "inflation_radius") return exactText(options.inflation_radius);
  if (name == "cost_scaling_factor") return exactText(options.cost_scaling_factor);
  if (name == "orientation_mode") return std::to_string(static_cast<int>(options.orientation_mode));
  if (name == "landmarks") return std::to_string(options.landmarks);
  for (const auto& [parameter, value] : eaci::parameterValues(params)) {
    if (parameter != name) continue;
    return std::visit(
        [](const auto& v) -> std::string {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, bool>) return boolText(v);
          else if constexpr (std::is_same_v<T, double>) return exactText(v);
          else if constexpr (std::is_same_v<T, std::string>) return v;
          else return std::to_string(v);
        },
        value);
  }
  throw eaci::ParameterError("unknown parameter '" + name + "'");
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
  return e.str();
}

std::string parameterNamedIn(const std::string& sentence) {
  std::string best;
  auto consider = [&](const std::string& name) {
    const bool prefix = sentence.compare(0, name.size(), name) == 0 &&
                        (sentence.size() == name.size() || sentence[name.size()] == ' ' || sentence[name.size()] == ':');
    if (prefix && name.size() > best.size()) best = name;
  };
  for (const std::string& name : eaci::parameterNames()) consider(name);
  for (const std::string& name : rosOptionNames()) consider(name);
  return best;
}

}  // namespace eaci_ros
