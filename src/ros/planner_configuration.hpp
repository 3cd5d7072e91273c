// The parameters a planner (node or move_base plugin) plans with: read from the parameter
// server at start, changed at run time with dynamic_reconfigure (cfg/EaciPlanner.cfg) in the
// same namespace, never replaced by defaults in silence, and handed to the planning service
// (`apply`), which takes only its own short configuration lock: no lock of ours is held
// while a plan runs, so reconfiguring never waits for a plan and never closes a lock cycle.
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

#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "reconfigured_parameters.hpp"
#include "ros_parameters.hpp"

namespace eaci_ros {

class PlannerConfiguration {
 public:
  // Receives every configuration in force: the parameters and options, and "" or the sentence
  // that refuses plans. Called from the constructor and from dynamic_reconfigure's callbacks.
  using Apply = std::function<void(const eaci::Parameters&, const RosPlannerOptions&, const std::string& error)>;

  // Reads the parameters under `nh` (a private namespace), logs which defaults are in force
  // (the robot-ready ones, rosDefaultParameters()) and what the parameter server set, applies
  // them, and serves them with dynamic_reconfigure. `who` starts the log lines.
  PlannerConfiguration(const ros::NodeHandle& nh, std::string who, Apply apply);

  // The configuration in force (for the node's map inflation options). Thread-safe.
  RosPlannerOptions options() const;

 private:
  void onReconfigure(PlannerConfig& config, std::uint32_t level);

  std::string namespace_;
  std::string who_;
  Apply apply_;
  mutable std::mutex mutex_;  // guards the values below against options(); never held while applying
  eaci::Parameters params_;
  RosPlannerOptions options_;
  std::string error_;
  PlannerConfig last_config_;  // the config as last applied: a reconfigure sets only what it changed
  // A bad value at start: the parameter, the config's value for it then, the sentence.
  bool start_problem_ = false;
  std::string start_problem_parameter_;
  std::string start_problem_value_;
  bool started_ = false;
  boost::recursive_mutex server_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<PlannerConfig>> server_;
};

}  // namespace eaci_ros
