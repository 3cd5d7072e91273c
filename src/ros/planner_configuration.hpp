// The parameters a planner (node or move_base plugin) plans with: read from the parameter
// server at start, changed at run time with dynamic_reconfigure (cfg/EaciPlanner.cfg) in the
// same namespace, never replaced by defaults in silence.
//
// A bad value, at start or through dynamic_reconfigure, sets error(): one sentence naming the
// parameter by its full name ("/move_base/EaciGlobalPlanner/aco_rho must be in (0, 1] (got
// 1.5)"); while it is set the planner refuses every plan with that sentence. A reconfigure that
// leaves every value valid clears it. A bad value at start stays until a reconfigure changes
// that parameter (dynamic_reconfigure shows a value it could not read, e.g. a string for a
// number, as its default: only a new value counts as the fix); one that cannot change at run
// time (occupied_threshold, robot_radius) stays until the node is restarted with a good one.
#pragma once

#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

#include <memory>
#include <mutex>
#include <string>

#include "reconfigured_parameters.hpp"
#include "ros_parameters.hpp"

namespace eaci_ros {

class PlannerConfiguration {
 public:
  // Reads the parameters under `nh` (a private namespace) and serves them there with
  // dynamic_reconfigure. New values are applied with `plan_mutex` held, the lock every plan
  // holds, so never in the middle of a plan. `who` starts the log lines. Do not hold
  // `plan_mutex` while constructing (the server applies the start values at once).
  PlannerConfiguration(const ros::NodeHandle& nh, std::mutex& plan_mutex, std::string who);

  // Read these with `plan_mutex` held.
  const eaci::Parameters& params() const { return params_; }
  const RosPlannerOptions& options() const { return options_; }
  const std::string& error() const { return error_; }  // "" = plans may run

 private:
  void onReconfigure(PlannerConfig& config, std::uint32_t level);

  std::string namespace_;
  std::mutex& plan_mutex_;
  std::string who_;
  eaci::Parameters params_;
  RosPlannerOptions options_;
  std::string error_;
  // A bad value at start: the parameter, the config's value for it then, the sentence.
  bool start_problem_ = false;
  std::string start_problem_parameter_;
  std::string start_problem_value_;
  bool started_ = false;
  boost::recursive_mutex server_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<PlannerConfig>> server_;
};

}  // namespace eaci_ros
