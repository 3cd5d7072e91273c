// What a ROS planner (the move_base plugin, the planner node) plans with besides the core's
// parameters: the ROS options global_planner users know, their text forms and ranges, and the
// robot-ready defaults. No ROS headers: the planning service and its tests use it without ROS.
#pragma once

#include <string>
#include <vector>

#include "eaci/planner/parameters.hpp"
#include "eaci/path/orientation.hpp"
#include "eaci/planner.hpp"

namespace eaci_service {

struct RosPlannerOptions {
  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;  // ~algorithm: eaci | aco | maaco | astar
  double default_tolerance = 0.0;   // m: the route ends on the cell nearest the goal within it that the start can reach
  int occupied_threshold = 65;      // nav_msgs/OccupancyGrid value (0..100) at or above which a cell is an obstacle
  bool publish_plan = true;
  double max_planning_time = 1.0;   // s; the best route so far is returned when it runs out; 0 = no limit
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
  // A replan to the same goal (the same cell, the same costmap frame and configuration) keeps
  // the route sent last, rejoined from the robot's cell, while it costs at most (1 + this) x
  // the new route by the planner's measure (eaci/path/route_hysteresis.hpp): successive plans
  // do not swap between routes of nearly equal cost. 0 = every plan sends its own route.
  double route_hysteresis = 0.0;
  // With turn_cost > 0, a route also pays turn_cost x the turn from its last move onto the
  // goal's heading (eaci::EndHeadings; the heading orientation_mode drives along, travelHeading):
  // it arrives lined up with the goal where the costs are close, and the smoother keeps the
  // leg it arrives along. A goal whose quaternion is not a rotation (all zeros) has no heading.
  // The robot's own heading is not priced: on replans while the car drives, a priced start
  // heading kept the route going straight on past a bend it should have started to take
  // (docs/ros.md, "Arriving lined up"). false: the goal turns nothing.
  bool price_goal_heading = true;
  // m: the plan runs this far on past the goal along the way it arrives, then ends at the goal
  // pose (src/service/past_goal.hpp): dwa_local_planner keeps the car's speed until it is
  // within xy_goal_tolerance of the goal instead of crawling the last decimetres. Only through
  // cells the route could enter; 0 = the plan ends at the goal. In [0, 0.5].
  double run_past_goal = 0.0;
  // m: a plan whose route leaves more than 90 deg off the robot's heading begins with an arc of
  // this radius round the robot, from its heading the shorter way onto the route's
  // (src/service/start_turn.hpp): dwa_local_planner's nose point follows it and the robot turns
  // in place the short way round. Set it to dwa's forward_point_distance. 0 = off. In [0, 0.5].
  double lead_start_turn = 0.0;
};

// The core parameters a robot plans with when its configuration sets none (the move_base
// plugin and the planner node from one line of configuration): the paper's colony (m = 50,
// Nc_max = 100, alpha, beta, Q, kappa, lambda, epsilon) made robot-ready: allow_unknown true
// (as navfn and global_planner), smooth_path true (a robot drives the smoothed route), early
// stopping after 10 iterations without a cheaper route or once within 1 % of the cheapest
// route (stop_gap 0.01), ants within 4 moves of the cheapest route (region_margin 4); one
// thread, as the core's default, so a plan leaves the other cores to the controller and SLAM
// (two threads saved 10-14 % of a plan on 1600 x 1600 cells, docs/ros.md). With
// RosPlannerOptions{} (max_planning_time 1 s) these are what one line of configuration plans
// with; config/eaci_planner.yaml is exactly these values (test_planning_service checks it). The
// paper's own protocol (every iteration) is config/paper_benchmark.yaml and the core's
// eaci::Parameters{} (the CLI's and the benchmarks' defaults).
eaci::Parameters rosDefaultParameters();

// The parameters of rosDefaultParameters() that differ from the paper's (eaci::Parameters{}),
// as "name value" pairs, for the start-up log line.
std::string robotDefaultsSummary();

// Every name a ROS planner reads: the core's table (eaci::parameterNames()) and the options above.
std::vector<std::string> rosParameterNames();

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
