// Where a plan begins when its route leaves behind the robot (~lead_start_turn). dwa_local_planner
// scores a turn in place by where its nose point (forward_point_distance ahead of the robot) ends,
// counted in 4-connected cells to the plan, and breaks ties by the order it samples in (clockwise
// first). With a route that leaves straight from under the robot, a nose swung either way ends
// about as far from it, so which way the robot turns is an accident of the first sample or of a
// creep's twist: on the lab, from (4.22, 0.59) facing -57 deg with a route north, both navfn's plans
// and EACI's turned the car 225 deg clockwise where 147 deg anticlockwise would do (docs/ros.md,
// "Turning the short way round"). A plan that begins with the arc the nose sweeps on the short way
// round puts that way on the plan, and dwa turns that way, provided it can start a turn in place
// from rest (acc_lim_theta x its sim period at least min_vel_theta).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/map_frame.hpp"

namespace eaci_service {

// The points a plan begins with after `start` (world, the robot's position) when its route
// leaves more than 90 deg off `start_yaw` (the robot's heading, the costmap frame's yaw): points
// `radius` m from the start, every 30 deg from the heading round the shorter way onto the route's
// direction (towards its first point at least 2 x radius away), the last one on that direction.
// Empty when radius is not positive, the yaw is not finite, the route turns 90 deg or less, it
// has no point that far, or an arc point's cell, or a cell between two of them, is off the map,
// an obstacle or unknown in `view` (knownFree).
std::vector<Eigen::Vector2d> startTurnArc(const eaci::GridView& view, const eaci::MapFrame& frame,
                                          const eaci::CellPath& route, const Eigen::Vector2d& start,
                                          double start_yaw, double radius);

}  // namespace eaci_service
