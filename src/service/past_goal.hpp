// Where a plan runs on to past its goal (~run_past_goal). dwa_local_planner (and
// base_local_planner's trajectory scoring) slows a robot down for the end of its global plan:
// a trajectory that ends beyond the plan's last pose is far from the path and from the goal at
// once, so near the goal only ever slower ones score best, and the car crawls the last
// decimetres into the goal (docs/ros.md, "Running on past the goal"). A plan whose path runs a
// few centimetres on past the goal along its last leg, and then ends at the goal pose, keeps the
// car's speed until it is within xy_goal_tolerance of the goal. navfn's plans happen to do this
// on the side its half-cell offset points to: their potential's path ends half a cell off the
// goal, and the goal pose is appended after it.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/map_frame.hpp"

namespace eaci_service {

// The point `distance` metres on past `goal` (world) along the way `route` (its cells, the last
// one the goal's) arrives: from its last cell at least two cells before the goal to the goal.
// Nothing when distance is not positive, the route is shorter than that, or a cell on the way
// from the goal's cell to the point's (eaci::traverseSegment: every cell the line between their
// centres passes or touches) is off the map, an obstacle or unknown in `view`.
std::optional<Eigen::Vector2d> pointPastGoal(const eaci::GridView& view, const eaci::MapFrame& frame,
                                             const eaci::CellPath& route, const Eigen::Vector2d& goal,
                                             double distance);

}  // namespace eaci_service
