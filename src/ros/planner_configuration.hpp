// The parameters a planner (node or move_base plugin) plans with: read from the parameter
// server at start, changed at run time with dynamic_reconfigure (cfg/EaciPlanner.cfg) in the
// same namespace, both by name through the one parameter table (setRosParameter(),
// planner_options.hpp), and handed to the planning service (`apply`), which takes only its own
// short configuration lock: no lock of ours is held while a plan runs.
//
// A bad value on the parameter server at start refuses every plan with one sentence naming it
// by its full name ("/move_base/EaciGlobalPlanner/aco_rho must be in (0, 1] (got 1.5)") until a
// reconfigure sets that parameter to a good value (one that cannot change at run time, e.g.
// occupied_threshold, until a restart). A bad value from dynamic_reconfigure is rejected: an
// error names it, the values in force stay (plans go on with them) and are written back into
// the config, so rqt_reconfigure shows what is in force. Values outside the cfg's min/max never
// arrive: dynamic_reconfigure clamps them (the change is logged).
#pragma once

#include <dynamic_reconfigure/server.h>
#include <eaci_planner/EaciPlannerConfig.h>
#include <ros/ros.h>

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "planner_options.hpp"

namespace eaci_ros {

// The ROS-free planning service (src/service) is what these adapters wrap.
using namespace eaci_service;

using PlannerConfig = eaci_planner::EaciPlannerConfig;

// Every value of `config` by name, as setRosParameter() reads it.
std::map<std::string, std::string> configTexts(const PlannerConfig& config);

// Sets the values of `config` that differ from `previous` (every value when null) in `params`
// and `options` and validates the result: "" or one sentence starting with the name of the
// first bad parameter (`params` and `options` partly set then: use copies). `changes`, when
// given, receives "name value" of each value set; `changed`, the name of each.
std::string applyConfig(const PlannerConfig& config, const PlannerConfig* previous, eaci::Parameters& params,
                        RosPlannerOptions& options, std::string* changes = nullptr,
                        std::vector<std::string>* changed = nullptr);

// Sets every value of `config` to the one in `params` and `options` (a seed wider than an int,
// which the config cannot hold, leaves the config's).
void storeInConfig(const eaci::Parameters& params, const RosPlannerOptions& options, PlannerConfig& config);

class PlannerConfiguration {
 public:
  // Receives every configuration in force: the parameters and options, and "" or the sentence
  // that refuses plans. Called from the constructor and from dynamic_reconfigure's callbacks.
  using Apply = std::function<void(const eaci::Parameters&, const RosPlannerOptions&, const std::string& error)>;

  // Reads the parameters under `nh` (a private namespace) over the robot-ready defaults
  // (rosDefaultParameters(), RosPlannerOptions{}), logs them, applies them, and serves them
  // with dynamic_reconfigure. `who` starts the log lines.
  PlannerConfiguration(const ros::NodeHandle& nh, std::string who, Apply apply);

  // The options in force (for the node's map inflation). Thread-safe.
  RosPlannerOptions options() const;

 private:
  void onReconfigure(PlannerConfig& config);

  std::string namespace_;
  std::string who_;
  Apply apply_;
  mutable std::mutex mutex_;  // guards params_ and options_ against options(); never held while applying
  eaci::Parameters params_;
  RosPlannerOptions options_;
  std::string start_error_;      // a bad value at start: the sentence that refuses plans ...
  std::string start_parameter_;  // ... and its parameter, which a reconfigure must set
  PlannerConfig in_force_;       // the config as last written back
  bool started_ = false;
  boost::recursive_mutex server_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<PlannerConfig>> server_;
};

}  // namespace eaci_ros
