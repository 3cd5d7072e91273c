#include "ros_parameters.hpp"

#include <XmlRpcValue.h>

#include <cmath>
#include <sstream>

namespace eaci_ros {
namespace {

// A parameter server value as the text setParameter() parses.
std::string asText(const std::string& name, XmlRpc::XmlRpcValue& value) {
  std::ostringstream text;
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean: return static_cast<bool>(value) ? "true" : "false";
    case XmlRpc::XmlRpcValue::TypeInt: text << static_cast<int>(value); return text.str();
    case XmlRpc::XmlRpcValue::TypeDouble:
      text.precision(17);
      text << static_cast<double>(value);
      return text.str();
    case XmlRpc::XmlRpcValue::TypeString: return static_cast<std::string>(value);
    default: throw eaci::ParameterError(name + " must be a number, a boolean or a string");
  }
}

template <typename T>
T readScalar(const ros::NodeHandle& nh, const std::string& name, T fallback) {
  if (!nh.hasParam(name)) return fallback;
  T value = fallback;
  if (!nh.getParam(name, value)) {
    // ints are acceptable where doubles are expected
    if constexpr (std::is_same_v<T, double>) {
      int as_int = 0;
      if (nh.getParam(name, as_int)) return as_int;
    }
    throw eaci::ParameterError(nh.resolveName(name) + " has the wrong type");
  }
  return value;
}

}  // namespace

void readParameters(const ros::NodeHandle& nh, eaci::Parameters& params, RosPlannerOptions& options) {
  params.allow_unknown = true;  // the ROS default, as navfn and global_planner
  params.smooth_path = true;    // robots drive the smoothed route
  if (nh.hasParam("obstacle_cost") && !nh.hasParam("lethal_cost"))
    params.lethal_cost = readScalar<int>(nh, "obstacle_cost", params.lethal_cost);
  for (const std::string& name : eaci::parameterNames()) {
    if (!nh.hasParam(name)) continue;
    XmlRpc::XmlRpcValue value;
    nh.getParam(name, value);
    eaci::setParameter(params, name, asText(nh.resolveName(name), value));
  }
  if (params.allow_corner_cutting) {
    ROS_WARN("%s: allow_corner_cutting is for the paper's benchmark only; a robot never cuts corners: ignored",
             nh.getNamespace().c_str());
    params.allow_corner_cutting = false;
  }
  eaci::validate(params);

  const std::string algorithm = readScalar<std::string>(nh, "algorithm", "eaci");
  if (!eaci::parseAlgorithm(algorithm, options.algorithm))
    throw eaci::ParameterError(nh.resolveName("algorithm") + " must be eaci, aco or astar (got '" + algorithm + "')");
  options.default_tolerance = readScalar<double>(nh, "default_tolerance", options.default_tolerance);
  options.occupied_threshold = readScalar<int>(nh, "occupied_threshold", options.occupied_threshold);
  options.publish_plan = readScalar<bool>(nh, "publish_plan", options.publish_plan);
  options.max_planning_time = readScalar<double>(nh, "max_planning_time", options.max_planning_time);
  options.visualize_pheromone = readScalar<bool>(nh, "visualize_pheromone", options.visualize_pheromone);
  options.robot_radius = readScalar<double>(nh, "robot_radius", options.robot_radius);
  if (nh.hasParam("orientation_mode")) {
    XmlRpc::XmlRpcValue mode;
    nh.getParam("orientation_mode", mode);
    try {
      options.orientation_mode = eaci::orientationModeFromString(asText(nh.resolveName("orientation_mode"), mode));
    } catch (const std::invalid_argument& e) {
      throw eaci::ParameterError(nh.resolveName("orientation_mode") + ": " + e.what());
    }
  }

  if (!std::isfinite(options.default_tolerance) || options.default_tolerance < 0)
    throw eaci::ParameterError(nh.resolveName("default_tolerance") + " must be a distance >= 0");
  if (options.occupied_threshold < 1 || options.occupied_threshold > 100)
    throw eaci::ParameterError(nh.resolveName("occupied_threshold") + " must be in 1..100");
  if (!std::isfinite(options.robot_radius) || options.robot_radius < 0)
    throw eaci::ParameterError(nh.resolveName("robot_radius") + " must be a distance >= 0");
  if (!std::isfinite(options.max_planning_time) || options.max_planning_time < 0)
    throw eaci::ParameterError(nh.resolveName("max_planning_time") + " must be >= 0 seconds (0 = no limit)");
}

}  // namespace eaci_ros
