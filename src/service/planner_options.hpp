// What a ROS planner (the move_base plugin, the planner node) plans with besides the core's
// parameters: the ROS options global_planner users know, their text forms and ranges, and the
// robot-ready defaults. No ROS headers: the planning service and its tests use it without ROS.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "eaci/planner/parameters.hpp"
#include "eaci/path/orientation.hpp"
#include "eaci/planner.hpp"

namespace eaci_service {

struct RosPlannerOptions {
  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;  // ~algorithm: eaci | astar (the paper's baselines: the CLI)
  double default_tolerance = 0.0;   // m: the route ends on the cell nearest the goal within it that the start can reach
  int occupied_threshold = 65;      // nav_msgs/OccupancyGrid value (0..100) at or above which a cell is an obstacle
  bool publish_plan = true;
  double max_planning_time = 1.0;   // s, at most kMaxPlanningTime; the best route so far is returned when it
                                    // runs out; 0 = no limit
                                    // (move_base holds its costmap lock around the plan)
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

// The core parameters a robot plans with when its configuration sets none (the move_base
// plugin and the planner node from one line of configuration): the paper's colony (m = 50,
// Nc_max = 100, alpha, beta, Q, kappa, lambda, epsilon) made robot-ready: allow_unknown true
// (as navfn and global_planner), cost_factor 0.8 (navfn's weighting of the costmap; global_planner's
// 3 takes wider doors, longer routes: 1.05-1.12 x navfn's arrival time on maps nobody tuned on,
// docs/ros.md "Measured"), smooth_path true (a robot drives the smoothed route) with its corners
// rounded (round_corners 2, smooth_tolerance 0.1, fixed: not ROS parameters), early
// stopping after 10 iterations without a cheaper route or once within 1 % of the cheapest
// route (stop_gap 0.01), ants within 4 moves of the cheapest route (region_margin 4); one
// thread, as the core's default, so a plan leaves the other cores to the controller and SLAM
// (two threads saved 10-14 % of a plan on 1600 x 1600 cells, docs/notebook/2026-12-03-concurrency-time-limit-threads.md). With
// RosPlannerOptions{} (max_planning_time 1 s) these are what one line of configuration plans
// with; config/eaci_planner.yaml is exactly these values (test_planning_service checks it). The
// paper's own protocol (every iteration) is config/paper_benchmark.yaml and the core's
// eaci::Parameters{} (the CLI's and the benchmarks' defaults).
eaci::Parameters rosDefaultParameters();

// The parameters of rosDefaultParameters() that differ from the paper's (eaci::Parameters{}),
// as "name value" pairs, for the start-up log line.
std::string robotDefaultsSummary();

// The longest max_planning_time, s (a plan's deadline must fit the steady clock).
constexpr double kMaxPlanningTime = 3600.0;

// Every name a ROS planner reads: the robot's parameters (robotParameterNames), the colony's
// research parameters (colonyParameterNames), and the options set at start (occupied_threshold,
// robot_radius, inflation_radius, cost_scaling_factor, landmarks). The core's other parameters
// (the ACO and MAACO baselines', smooth_tolerance, round_corners, turn_cost_unit,
// allow_corner_cutting) are the CLI's and the benchmarks' only.
std::vector<std::string> rosParameterNames();
// What a builder sets for a robot (dynamic_reconfigure's first group).
const std::vector<std::string>& robotParameterNames();
// The colony's own parameters (its research group): on a robot they change only how long a plan takes.
const std::vector<std::string>& colonyParameterNames();
// Names a ROS planner does not read but a configuration may still hold (the core's other
// parameters, options of earlier versions), each with the reason: said at start when set.
std::vector<std::pair<std::string, std::string>> unreadParameters();

// Sets one core parameter (eaci::setParameter) or ROS option by name from its text form.
// Throws eaci::ParameterError with a sentence starting with the name for an unknown name or a
// value of the wrong type; ranges are rosValidationError()'s job.
void setRosParameter(eaci::Parameters& params, RosPlannerOptions& options, const std::string& name,
                     const std::string& text);

// The value of a core parameter or ROS option (orientation_mode as global_planner's number).
// Throws eaci::ParameterError for an unknown name.
eaci::ParameterValue rosParameterValue(const eaci::Parameters& params, const RosPlannerOptions& options,
                                       const std::string& name);

// A value in the text form setRosParameter() reads back (numbers exact).
std::string valueText(const eaci::ParameterValue& value);

// "" when every value is in range, else one sentence starting with the parameter's name.
std::string rosValidationError(const eaci::Parameters& params, const RosPlannerOptions& options);

}  // namespace eaci_service
