// The headings at a route's ends (issue #30): the way the robot faces where it starts, and the
// way it must face at the goal. With turn_cost > 0 a route also pays for the turn from the start
// heading onto its first move and from its last move onto the goal heading, at the same price
// per radian as its corners, so a route that leaves the way the robot faces and enters the goal
// lined up with its yaw wins where the costs are close. Without a heading (NaN) its end turns
// nothing, as before.
//
// Angles are grid angles: radians counter-clockwise from east (column + 1), north being row - 1,
// so move direction d points at d x 45 degrees (grid/moves.hpp). On a costmap (y up the rows,
// MapFrame) that is the yaw in the costmap's frame.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

struct EndHeadings {
  double start = std::numeric_limits<double>::quiet_NaN();  // radians; NaN: any first move turns nothing
  double goal = std::numeric_limits<double>::quiet_NaN();   // radians; NaN: any last move turns nothing
  bool hasStart() const { return std::isfinite(start); }
  bool hasGoal() const { return std::isfinite(goal); }
};

// The turn between two headings (radians, any turn count): radians in [0, pi].
inline double angleBetween(double a, double b) { return std::abs(std::remainder(a - b, 2.0 * M_PI)); }

// The grid angle of the straight segment from cell a to cell b.
inline double headingOf(Cell a, Cell b) { return std::atan2(a.row - b.row, b.col - a.col); }

// The turn between heading `yaw` and move direction `dir`: radians in [0, pi].
inline double turnRadians(double yaw, int dir) { return angleBetween(static_cast<double>(dir) * kTurnStepRadians, yaw); }

// turn_cost x the turn from `yaw` onto each move direction; all 0 without a heading (NaN).
inline std::array<double, kDirections> headingTurnPrices(double yaw, double turn_cost) {
  std::array<double, kDirections> price{};
  if (std::isfinite(yaw))
    for (int d = 0; d < kDirections; ++d) price[d] = turn_cost * turnRadians(yaw, d);
  return price;
}

// The turns a route makes at its ends, radians: from the start heading onto its first move and
// from its last move onto the goal heading (each 0 without its heading); 0 for a route of one
// cell; NaN when its first or last two cells are not 8-neighbours (not a route).
inline double endTurnRadians(const CellPath& route, const EndHeadings& ends) {
  if (route.size() < 2) return 0.0;
  double turn = 0.0;
  if (ends.hasStart()) {
    const int first = directionBetween(route[0], route[1]);
    if (first < 0) return std::numeric_limits<double>::quiet_NaN();
    turn += turnRadians(ends.start, first);
  }
  if (ends.hasGoal()) {
    const int last = directionBetween(route[route.size() - 2], route.back());
    if (last < 0) return std::numeric_limits<double>::quiet_NaN();
    turn += turnRadians(ends.goal, last);
  }
  return turn;
}

}  // namespace eaci
