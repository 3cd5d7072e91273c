// Reading the planner's parameters from the ROS parameter server: every core parameter under
// its own name (the robot-ready defaults when absent, planner_options.hpp), plus what ROS users
// expect of a global planner.
#pragma once

#include <ros/ros.h>

#include <string>
#include <vector>

#include "planner_options.hpp"

namespace eaci_ros {

// A parameter that could not be used, with the sentence that names it (its full name, e.g.
// "/move_base/EaciGlobalPlanner/aco_rho must be in (0, 1] (got 1.5)").
struct ParameterProblem {
  std::string parameter;  // relative name, e.g. "aco_rho"
  std::string sentence;
};

// Fills `params` and `options` from `nh` (a private namespace), starting from
// rosDefaultParameters() and RosPlannerOptions{}. The cost model (neutral_cost, cost_factor,
// lethal_cost, allow_unknown) is in `params`; the older name obstacle_cost still sets
// lethal_cost. Each parameter is read on its own, so a bad one leaves the others read; the
// first bad one (wrong type, unknown word, out of range) is returned, never replaced by a
// default in silence. Corner cutting is always forbidden on a robot, whatever the parameter
// server says (a warning).
// `set_here`, when given, receives the names found on the parameter server.
std::vector<ParameterProblem> readParameters(const ros::NodeHandle& nh, eaci::Parameters& params,
                                             RosPlannerOptions& options, std::vector<std::string>* set_here = nullptr);

}  // namespace eaci_ros
