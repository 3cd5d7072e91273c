#include "planner_configuration.hpp"

#include <utility>

namespace eaci_ros {

PlannerConfiguration::PlannerConfiguration(const ros::NodeHandle& nh, std::string who, Apply apply)
    : namespace_(nh.getNamespace()), who_(std::move(who)), apply_(std::move(apply)) {
  std::vector<std::string> set_here;
  const std::vector<ParameterProblem> problems = readParameters(nh, params_, options_, &set_here);
  std::string set_list;
  for (const std::string& name : set_here) set_list += (set_list.empty() ? "" : ", ") + name;
  ROS_INFO("%s: robot-ready defaults in force (the paper's colony with %s; the paper's own protocol is "
           "config/paper_benchmark.yaml); set on the parameter server: %s",
           who_.c_str(), robotDefaultsSummary().c_str(), set_list.empty() ? "nothing" : set_list.c_str());
  if (!problems.empty()) {
    start_problem_ = true;
    start_problem_parameter_ = problems.front().parameter;
    error_ = problems.front().sentence;
    ROS_ERROR("%s: %s: refusing to plan until it is fixed", who_.c_str(), error_.c_str());
  }
  apply_(params_, options_, error_);
  // The server reads the same namespace (and writes back what it read); the first callback
  // replaces what it read by what readParameters() read, so both agree.
  server_ = std::make_unique<dynamic_reconfigure::Server<PlannerConfig>>(server_mutex_, nh);
  server_->setCallback([this](PlannerConfig& config, std::uint32_t level) { onReconfigure(config, level); });
}

RosPlannerOptions PlannerConfiguration::options() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return options_;
}

// Runs under the server's own mutex (one callback at a time).
void PlannerConfiguration::onReconfigure(PlannerConfig& config, std::uint32_t) {
  try {
    if (!started_) {
      // At start: the values readParameters() read (it reads what dynamic_reconfigure cannot,
      // e.g. orientation_mode by name, the older obstacle_cost, a seed wider than an int) are
      // the config's.
      started_ = true;
      storeInConfig(params_, options_, config);
      last_config_ = config;
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
    // Only what this reconfigure changed: a value the config cannot hold (a seed above INT_MAX)
    // stays as it was read.
    const std::string error = applyConfig(config, last_config_, params, options);
    last_config_ = config;
    if (!error.empty()) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        error_ = namespace_ + "/" + error;
      }
      ROS_ERROR("%s: reconfigured: %s: refusing to plan until it is fixed", who_.c_str(), error_.c_str());
      apply_(params_, options_, error_);
      return;
    }
    const bool was_bad = !error_.empty();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      params_ = params;
      options_ = options;
      error_.clear();
    }
    apply_(params_, options_, error_);
    if (was_bad) ROS_INFO("%s: reconfigured: the parameters are valid again; planning resumes", who_.c_str());
    else ROS_INFO("%s: reconfigured", who_.c_str());
  } catch (const std::exception& e) {  // never into dynamic_reconfigure's (the host's) thread
    ROS_ERROR("%s: reconfigure failed: %s; the parameters in force stay", who_.c_str(), e.what());
  }
}

}  // namespace eaci_ros
