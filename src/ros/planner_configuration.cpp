#include "planner_configuration.hpp"

#include <XmlRpcValue.h>
#include <dynamic_reconfigure/Config.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace eaci_ros {
namespace {

// A parameter server value as the text setRosParameter() reads.
std::string asText(const std::string& name, XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean: return static_cast<bool>(value) ? "true" : "false";
    case XmlRpc::XmlRpcValue::TypeInt: return std::to_string(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble: return valueText(eaci::ParameterValue{static_cast<double>(value)});
    case XmlRpc::XmlRpcValue::TypeString: return static_cast<std::string>(value);
    default: throw eaci::ParameterError(name + " must be a number, a boolean or a string");
  }
}

// The parameter a sentence of setRosParameter() or rosValidationError() starts with.
std::string leadingName(const std::string& sentence) { return sentence.substr(0, sentence.find_first_of(" :")); }

}  // namespace

std::map<std::string, std::string> configTexts(const PlannerConfig& config) {
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  std::map<std::string, std::string> texts;
  for (const auto& p : message.ints) texts[p.name] = std::to_string(p.value);
  for (const auto& p : message.doubles) texts[p.name] = valueText(eaci::ParameterValue{p.value});
  for (const auto& p : message.bools) texts[p.name] = p.value ? "true" : "false";
  for (const auto& p : message.strs) texts[p.name] = p.value;
  return texts;
}

std::string applyConfig(const PlannerConfig& config, const PlannerConfig* previous, eaci::Parameters& params,
                        RosPlannerOptions& options, std::string* changes, std::vector<std::string>* changed) {
  const auto before = previous ? configTexts(*previous) : std::map<std::string, std::string>{};
  try {
    for (const auto& [name, text] : configTexts(config)) {
      if (previous && before.at(name) == text) continue;
      setRosParameter(params, options, name, text);
      if (changes) *changes += (changes->empty() ? "" : ", ") + name + " " + text;
      if (changed) changed->push_back(name);
    }
  } catch (const eaci::ParameterError& e) {
    return e.what();
  }
  return rosValidationError(params, options);
}

void storeInConfig(const eaci::Parameters& params, const RosPlannerOptions& options, PlannerConfig& config) {
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  for (auto& p : message.ints) {
    const eaci::ParameterValue v = rosParameterValue(params, options, p.name);
    const auto* i = std::get_if<std::int64_t>(&v);
    const auto* u = std::get_if<std::uint64_t>(&v);  // the seed
    if (i && *i >= std::numeric_limits<int>::min() && *i <= std::numeric_limits<int>::max()) p.value = static_cast<int>(*i);
    else if (u && *u <= static_cast<std::uint64_t>(std::numeric_limits<int>::max())) p.value = static_cast<int>(*u);
  }
  for (auto& p : message.doubles) p.value = std::get<double>(rosParameterValue(params, options, p.name));
  for (auto& p : message.bools) p.value = std::get<bool>(rosParameterValue(params, options, p.name));
  for (auto& p : message.strs) p.value = std::get<std::string>(rosParameterValue(params, options, p.name));
  config.__fromMessage__(message);
}

PlannerConfiguration::PlannerConfiguration(const ros::NodeHandle& nh, std::string who, Apply apply)
    : namespace_(nh.getNamespace()), who_(std::move(who)), apply_(std::move(apply)), params_(rosDefaultParameters()) {
  std::string set_here;
  for (const std::string& name : rosParameterNames()) {
    const std::string key = name == "lethal_cost" && !nh.hasParam(name) ? "obstacle_cost" : name;  // its older name
    if (!nh.hasParam(key)) continue;
    set_here += (set_here.empty() ? "" : ", ") + key;
    try {
      XmlRpc::XmlRpcValue value;
      nh.getParam(key, value);
      setRosParameter(params_, options_, name, asText(name, value));
    } catch (const eaci::ParameterError& e) {  // the first bad one is named, under the name the user wrote
      if (start_error_.empty()) start_error_ = key + std::string(e.what()).substr(leadingName(e.what()).size());
    }
  }
  for (const auto& [name, reason] : unreadParameters())
    if (nh.hasParam(name)) ROS_WARN("%s: %s is not read here (%s): ignored", who_.c_str(), name.c_str(), reason.c_str());
  if (start_error_.empty()) start_error_ = rosValidationError(params_, options_);
  start_parameter_ = leadingName(start_error_);
  if (start_parameter_ == "obstacle_cost") start_parameter_ = "lethal_cost";
  ROS_INFO("%s: robot-ready defaults in force (the paper's colony with %s; the paper's own protocol is "
           "config/paper_benchmark.yaml); set on the parameter server: %s",
           who_.c_str(), robotDefaultsSummary().c_str(), set_here.empty() ? "nothing" : set_here.c_str());
  if (!start_error_.empty()) {
    start_error_ = namespace_ + "/" + start_error_;
    ROS_ERROR("%s: %s: refusing to plan until it is fixed", who_.c_str(), start_error_.c_str());
  }
  apply_(params_, options_, start_error_);
  // The server reads the same namespace; its first callback replaces what it read (clamped to
  // the cfg's ranges, a value it could not read as the default) by what was read above.
  server_ = std::make_unique<dynamic_reconfigure::Server<PlannerConfig>>(server_mutex_, nh);
  server_->setCallback([this](PlannerConfig& config, std::uint32_t) { onReconfigure(config); });
}

RosPlannerOptions PlannerConfiguration::options() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return options_;
}

// Runs under the server's own mutex (one callback at a time). `config` goes back to
// rqt_reconfigure (and the parameter server) as this leaves it: the values in force.
void PlannerConfiguration::onReconfigure(PlannerConfig& config) {
  try {
    if (started_) {
      eaci::Parameters params = params_;
      RosPlannerOptions options = options_;
      std::string changes;  // only what this reconfigure changed: a seed above INT_MAX stays as read
      std::vector<std::string> changed;
      const std::string error = applyConfig(config, &in_force_, params, options, &changes, &changed);
      if (!error.empty()) {
        std::string stays;
        try {
          const std::string name = leadingName(error);
          stays = " (" + name + " stays " + valueText(rosParameterValue(params_, options_, name)) + ")";
        } catch (const eaci::ParameterError&) {
        }
        ROS_ERROR("%s: reconfigure rejected: %s/%s; the values in force stay%s", who_.c_str(), namespace_.c_str(),
                  error.c_str(), stays.c_str());
      } else {
        if (std::find(changed.begin(), changed.end(), start_parameter_) != changed.end()) start_error_.clear();
        {
          std::lock_guard<std::mutex> lock(mutex_);
          params_ = params;
          options_ = options;
        }
        apply_(params_, options_, start_error_);
        ROS_INFO("%s: reconfigured: %s", who_.c_str(), changes.empty() ? "nothing changed" : changes.c_str());
      }
      if (!start_error_.empty())
        ROS_ERROR("%s: %s: refusing to plan until it is fixed", who_.c_str(), start_error_.c_str());
    }
    started_ = true;
    storeInConfig(params_, options_, config);
    in_force_ = config;
  } catch (const std::exception& e) {  // never into dynamic_reconfigure's (the host's) thread
    ROS_ERROR("%s: reconfigure failed: %s; the values in force stay", who_.c_str(), e.what());
  } catch (...) {
    ROS_ERROR("%s: reconfigure failed with an unknown exception; the values in force stay", who_.c_str());
  }
}

}  // namespace eaci_ros
