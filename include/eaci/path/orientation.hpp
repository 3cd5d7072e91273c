// Headings of the poses along a route, set as global_planner's orientation_mode sets them (none, forward, interpolate,
// forward_then_interpolate, backward, leftward, rightward), so move_base users get the behaviour they know.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace eaci {

// In global_planner's order: the numbers are its orientation_mode values 0..6.
enum class OrientationMode { kNone, kForward, kInterpolate, kForwardThenInterpolate, kBackward, kLeftward, kRightward };

inline const char* toString(OrientationMode mode) {
  switch (mode) {
    case OrientationMode::kNone: return "none";
    case OrientationMode::kForward: return "forward";
    case OrientationMode::kInterpolate: return "interpolate";
    case OrientationMode::kForwardThenInterpolate: return "forward_then_interpolate";
    case OrientationMode::kBackward: return "backward";
    case OrientationMode::kLeftward: return "leftward";
    case OrientationMode::kRightward: return "rightward";
  }
  return "?";
}

// By name, or global_planner's number (0 none, 1 forward, 2 interpolate, 3 forward_then_interpolate,
// 4 backward, 5 leftward, 6 rightward); std::invalid_argument otherwise.
inline OrientationMode orientationModeFromString(const std::string& text) {
  for (auto mode : {OrientationMode::kNone, OrientationMode::kForward, OrientationMode::kInterpolate,
                    OrientationMode::kForwardThenInterpolate, OrientationMode::kBackward, OrientationMode::kLeftward,
                    OrientationMode::kRightward})
    if (text == toString(mode) || text == std::to_string(static_cast<int>(mode))) return mode;
  throw std::invalid_argument("'" + text +
                              "' is not one of: none, forward, interpolate, forward_then_interpolate, backward, "
                              "leftward, rightward (or 0-6)");
}

// The way a robot at `yaw` travels along a route oriented by `mode`: its yaw, or (backward,
// leftward, rightward: the route runs along the robot's -x, +y or -y axis) the yaw turned by
// pi, +pi/2 or -pi/2; NaN stays NaN. The planners price the turn from it onto the first move
// and off the last move onto the goal's (PlanOptions::end_headings).
inline double travelHeading(double yaw, OrientationMode mode) {
  switch (mode) {
    case OrientationMode::kBackward: return yaw + M_PI;
    case OrientationMode::kLeftward: return yaw + M_PI / 2;
    case OrientationMode::kRightward: return yaw - M_PI / 2;
    default: return yaw;
  }
}

// The turn from heading `from` to heading `to` the shorter way round, radians in [-pi, pi]
// (+ = anticlockwise).
inline double shortestAngle(double from, double to) { return std::remainder(to - from, 2.0 * M_PI); }

namespace detail {

// Headings from index `first` to `last` turn evenly from heading[first] to heading[last].
inline void interpolateHeadings(std::vector<double>& heading, std::size_t first, std::size_t last) {
  const double turn = shortestAngle(heading[first], heading[last]);
  for (std::size_t k = first + 1; k < last; ++k)
    heading[k] = heading[first] + turn * static_cast<double>(k - first) / static_cast<double>(last - first);
}
}  // namespace detail

// Heading (rad) of every point: the first and last are the start's and goal's own headings
// (except forward, whose first pose faces the second); in between, as global_planner's
// OrientationFilter does it:
//   none                      heading 0;
//   forward                   each point faces the next one;
//   interpolate               turning evenly from the start heading to the goal heading;
//   forward_then_interpolate  forward, then, over the final stretch whose direction stays within
//                             0.35 rad of the last segment's, turning evenly to the goal heading;
//   backward / leftward / rightward  forward turned by pi / -pi/2 / +pi/2: the robot's -x / +y / -y
//                             axis points along the route (global_planner's signs).
inline std::vector<double> orientPoints(const std::vector<Eigen::Vector2d>& points, double start_yaw, double goal_yaw,
                                        OrientationMode mode) {
  const std::size_t n = points.size();
  std::vector<double> heading(n, 0.0);
  if (n == 0) return heading;
  const auto faceNext = [&] {
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const Eigen::Vector2d d = points[k + 1] - points[k];
      heading[k] = d.squaredNorm() > 0 ? std::atan2(d.y(), d.x()) : (k > 0 ? heading[k - 1] : start_yaw);
    }
  };
  const auto faceNextTurnedBy = [&](double turn) {
    faceNext();
    for (std::size_t k = 0; k + 1 < n; ++k) heading[k] = std::remainder(heading[k] + turn, 2.0 * M_PI);
  };
  switch (mode) {
    case OrientationMode::kBackward:
      faceNextTurnedBy(M_PI);
      break;
    case OrientationMode::kLeftward:
      faceNextTurnedBy(-M_PI / 2);
      break;
    case OrientationMode::kRightward:
      faceNextTurnedBy(M_PI / 2);
      break;
    case OrientationMode::kNone:
      heading.front() = start_yaw;
      break;
    case OrientationMode::kForward:
      faceNext();
      break;
    case OrientationMode::kInterpolate:
      heading.front() = start_yaw;
      heading.back() = goal_yaw;
      detail::interpolateHeadings(heading, 0, n - 1);
      break;
    case OrientationMode::kForwardThenInterpolate: {
      faceNext();
      if (n >= 3) {
        std::size_t first = n - 3;  // global_planner: from the third-last pose back while straight
        const double last_direction = heading[n - 3];
        while (first > 0 && std::abs(shortestAngle(heading[first - 1], last_direction)) <= 0.35) --first;
        heading.front() = start_yaw;
        heading.back() = goal_yaw;
        detail::interpolateHeadings(heading, first, n - 1);
      }
      break;
    }
  }
  heading.back() = goal_yaw;
  return heading;
}

}  // namespace eaci
