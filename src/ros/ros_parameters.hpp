// Reading the planner's parameters from the ROS parameter server: every core parameter under
// its own name (the paper's defaults when absent), plus what ROS users expect of a global planner.
#pragma once

#include <ros/ros.h>

#include <string>
#include <vector>

#include "eaci/aco/parameters.hpp"
#include "eaci/path/orientation.hpp"
#include "eaci/planner.hpp"

namespace eaci_ros {

struct RosPlannerOptions {
  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;  // ~algorithm: eaci | aco | astar
  double default_tolerance = 0.0;   // m: a goal in an obstacle moves to the nearest free cell within it
  int occupied_threshold = 65;      // nav_msgs/OccupancyGrid value (0..100) at or above which a cell is an obstacle
  bool publish_plan = true;
  double max_planning_time = 5.0;   // s; the best route so far is returned when it runs out; 0 = no limit
  bool visualize_pheromone = false; // publish the final pheromone as a nav_msgs/OccupancyGrid
  double robot_radius = 0.0;        // m, planner node only: obstacles grow by it (the plugin has the costmap's inflation)
  // Planner node only, costmap_2d's inflation layer on the map it plans on: with inflation_radius > 0,
  // cells within robot_radius of an obstacle are inscribed obstacles (253) and cells out to
  // inflation_radius cost 252 x exp(-cost_scaling_factor x (distance - robot_radius)), so routes keep off walls.
  double inflation_radius = 0.0;    // m; 0 = no costs, obstacles grown by robot_radius only
  double cost_scaling_factor = 10.0;  // 1/m, costmap_2d's default
  eaci::OrientationMode orientation_mode = eaci::OrientationMode::kForward;  // global_planner's ~orientation_mode
  // Landmarks kept for the island route's search on maps from 256 x 256 cells (eaci::LandmarkCache):
  // made in the background after the first plan on a costmap, 4 bytes a cell each; 0 = none.
  int landmarks = 4;
};

// The core parameters with the ROS layer's defaults: allow_unknown true (as navfn and
// global_planner), smooth_path true (a robot drives the smoothed route); the rest the paper's.
eaci::Parameters rosDefaultParameters();

// The names of the ROS options above (algorithm, default_tolerance, ...).
const std::vector<std::string>& rosOptionNames();

// Sets one core parameter (eaci::setParameter) or ROS option by name from its text form.
// Throws eaci::ParameterError with a sentence starting with the name for an unknown name or a
// value of the wrong type; ranges are rosValidationError()'s job.
void setRosParameter(eaci::Parameters& params, RosPlannerOptions& options, const std::string& name,
                     const std::string& text);

// The value of a core parameter or ROS option in the text form setRosParameter() reads back
// (numbers exact, orientation_mode as global_planner's number). Throws eaci::ParameterError for
// an unknown name.
std::string rosParameterText(const eaci::Parameters& params, const RosPlannerOptions& options, const std::string& name);

// "" when every value is in range, else one sentence starting with the parameter's name.
std::string rosValidationError(const eaci::Parameters& params, const RosPlannerOptions& options);

// The parameter a sentence of setRosParameter() or rosValidationError() is about ("" if none).
std::string parameterNamedIn(const std::string& sentence);

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
std::vector<ParameterProblem> readParameters(const ros::NodeHandle& nh, eaci::Parameters& params,
                                             RosPlannerOptions& options);

}  // namespace eaci_ros
