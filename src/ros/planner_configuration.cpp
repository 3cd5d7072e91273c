#include "planner_configuration.hpp"

#include <utility>

namespace eaci_ros {

PlannerConfiguration::PlannerConfiguration(const ros::NodeHandle& nh, std::mutex& plan_mutex, std::string who)
    : namespace_(nh.getNamespace()), plan_mutex_(plan_mutex), who_(std::move(who)) {
  const std::vector<ParameterProblem> problems = readParameters(nh, params_, options_);
  if (!problems.empty()) {
    start_problem_ = true;
    start_problem_parameter_ = problems.front().parameter;
    error_ = problems.front().sentence;
    ROS_ERROR("%s: %s: refusing to plan until it is fixed", who_.c_str(), error_.c_str());
  }
  // The server reads the same namespace (and writes back what it read); the first callback
  // replaces what it read by what readParameters() read, so both agree.
  server_ = std::make_unique<dynamic_reconfigure::Server<PlannerConfig>>(server_mutex_, nh);
  server_->setCallback([this](PlannerConfig& config, std::uint32_t level) { onReconfigure(config, level); });
}

void PlannerConfiguration::onReconfigure(PlannerConfig& config, std::uint32_t) {
  std::lock_guard<std::mutex> between_plans(plan_mutex_);
  if (!started_) {
    // At start: the values readParameters() read (it reads what dynamic_reconfigure cannot,
    // e.g. orientation_mode by name, the older obstacle_cost) are the config's.
    started_ = true;
    storeInConfig(params_, options_, config);
    if (start_problem_) start_problem_value_ = configValue(config, start_problem_parameter_);
    return;
  }
  if (start_problem_) {
    if (configValue(config, start_problem_parameter_) == start_problem_value_) {
      ROS_ERROR("%s: reconfigured, but %s: refusing to plan until it is fixed", who_.c_str(), error_.c_str());
      return;
    }
    start_problem_ = false;
  }
  eaci::Parameters params = params_;
  RosPlannerOptions options = options_;
  const std::string error = applyConfig(config, params, options);
  if (!error.empty()) {
    error_ = namespace_ + "/" + error;
    ROS_ERROR("%s: reconfigured: %s: refusing to plan until it is fixed", who_.c_str(), error_.c_str());
    return;
  }
  params_ = params;
  options_ = options;
  if (!error_.empty()) ROS_INFO("%s: reconfigured: the parameters are valid again; planning resumes", who_.c_str());
  else ROS_INFO("%s: reconfigured", who_.c_str());
  error_.clear();
}

}  // namespace eaci_ros
