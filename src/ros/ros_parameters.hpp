// Reading the planner's parameters from the ROS parameter server: every core parameter under
// its own name (the paper's defaults when absent), plus what ROS users expect of a global planner.
#pragma once

#include <ros/ros.h>

#include <string>

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
  eaci::OrientationMode orientation_mode = eaci::OrientationMode::kForward;  // global_planner's ~orientation_mode
};

// Fills `params` and `options` from `nh` (a private namespace). The cost model (neutral_cost,
// cost_factor, lethal_cost, allow_unknown) is in `params`; allow_unknown defaults to true here,
// as in navfn and global_planner, and the older name obstacle_cost still sets lethal_cost;
// smooth_path defaults to true here (a robot drives the smoothed route).
// Throws eaci::ParameterError with a sentence naming the parameter for a wrong type or value.
// Corner cutting is always forbidden on a robot, whatever the parameter server says.
void readParameters(const ros::NodeHandle& nh, eaci::Parameters& params, RosPlannerOptions& options);

}  // namespace eaci_ros
