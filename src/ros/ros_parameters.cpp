#include "ros_parameters.hpp"

#include <XmlRpcValue.h>

#include <sstream>

namespace eaci_ros {
namespace {

// A parameter server value as the text setRosParameter() parses.
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


}  // namespace

std::vector<ParameterProblem> readParameters(const ros::NodeHandle& nh, eaci::Parameters& params,
                                             RosPlannerOptions& options, std::vector<std::string>* set_here) {
  params = rosDefaultParameters();
  options = RosPlannerOptions{};
  std::vector<ParameterProblem> problems;
  const std::string prefix = nh.getNamespace() + "/";
  auto read = [&](const std::string& name, const std::string& as) {
    if (!nh.hasParam(name)) return;
    if (set_here) set_here->push_back(name);
    try {
      XmlRpc::XmlRpcValue value;
      nh.getParam(name, value);
      setRosParameter(params, options, as, asText(as, value));
    } catch (const eaci::ParameterError& e) {
      // The sentence starts with the name it was set as; the user wrote `name`.
      std::string sentence = e.what();
      if (as != name && sentence.compare(0, as.size(), as) == 0) sentence = name + sentence.substr(as.size());
      problems.push_back({name, prefix + sentence});
    }
  };
  if (!nh.hasParam("lethal_cost")) read("obstacle_cost", "lethal_cost");
  for (const std::string& name : eaci::parameterNames()) read(name, name);
  for (const std::string& name : rosOptionNames()) read(name, name);
  if (params.allow_corner_cutting) {
    ROS_WARN("%s: allow_corner_cutting is for the paper's benchmark only; a robot never cuts corners: ignored",
             nh.getNamespace().c_str());
    params.allow_corner_cutting = false;
  }
  if (problems.empty()) {
    const std::string error = rosValidationError(params, options);
    if (!error.empty()) problems.push_back({parameterNamedIn(error), prefix + error});
  }
  return problems;
}

}  // namespace eaci_ros
