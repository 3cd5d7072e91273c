// Keeping the route a robot is driving when it replans (beyond the paper; issue #30). move_base
// asks for a new plan every 1 / planner_frequency seconds while the robot drives; where two
// routes cost nearly the same (either side of an obstacle, a bend taken at one corner or the
// next) successive plans may alternate between them and the robot swerves from one to the
// other. A replan to the same goal may instead keep the previous route, rejoined from where
// the robot is, while it costs no more than (1 + hysteresis) x the new one by the planner's
// own measure of a smoothed route (polylineObjective).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/end_headings.hpp"
#include "eaci/path/smoothing.hpp"

namespace eaci {

// What driving the polyline of cell centres `corners` costs by the planners' objective: each
// segment's cost (segmentCostAndPeak: its length in every cell weighted like a move into that
// cell) plus turn_cost x the heading change at each inner corner, in radians (the turning term
// of the search over (cell, heading) and the colonies), and at its ends from the start heading
// and onto the goal heading of `ends` where it has them. +infinity when a segment touches an
// obstacle or leaves the map. Consecutive equal cells add nothing and turn nothing.
inline double polylineObjective(const CostGrid& grid, const CellPath& corners, double turn_cost,
                                const EndHeadings& ends = {}) {
  double cost = 0.0;
  bool heading_known = ends.hasStart();
  double heading = ends.start;
  bool moved = false;
  for (std::size_t k = 1; k < corners.size(); ++k) {
    if (corners[k] == corners[k - 1]) continue;
    cost += segmentCost(grid, corners[k - 1], corners[k]);
    if (!std::isfinite(cost)) return std::numeric_limits<double>::infinity();
    const double next = headingOf(corners[k - 1], corners[k]);
    if (heading_known) cost += turn_cost * angleBetween(next, heading);
    heading = next;
    heading_known = true;
    moved = true;
  }
  if (ends.hasGoal() && moved)
    cost += turn_cost * angleBetween(ends.goal, heading);
  return cost;
}

// The previous route from `start` on: `start`, then the corners of `previous` after the point of
// it nearest to `start` (the foot of the perpendicular on its nearest segment, in cells). Empty
// when `previous` has no segment, `start` is its end, or that point lies more than `max_offset`
// cells from `start` (the robot has left the route: there is nothing to keep).
inline CellPath rejoinRoute(const CellPath& previous, Cell start, double max_offset) {
  if (previous.size() < 2) return {};
  double best = std::numeric_limits<double>::infinity();
  std::size_t next_corner = 0;  // the first corner after the nearest point
  for (std::size_t k = 1; k < previous.size(); ++k) {
    const double ax = previous[k - 1].col, ay = previous[k - 1].row;
    const double dx = previous[k].col - ax, dy = previous[k].row - ay;
    const double length2 = dx * dx + dy * dy;
    const double t = length2 > 0 ? std::clamp(((start.col - ax) * dx + (start.row - ay) * dy) / length2, 0.0, 1.0) : 1.0;
    const double offset = std::hypot(ax + t * dx - start.col, ay + t * dy - start.row);
    if (offset < best) {
      best = offset;
      next_corner = k;
    }
  }
  if (best > max_offset) return {};
  CellPath rejoined{start};
  for (std::size_t k = next_corner; k < previous.size(); ++k)
    if (!(previous[k] == rejoined.back())) rejoined.push_back(previous[k]);
  if (rejoined.size() < 2) return {};  // the robot stands on the goal: nothing to keep
  return rejoined;
}

}  // namespace eaci
