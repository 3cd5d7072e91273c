// A simulated 2-D laser scanner: ranges ray-cast on a world occupancy grid (which may hold what
// the planning map does not), with range noise. The defaults are the paper's M10P (Section 7,
// Table 4): 0.1-30 m, +-3 cm, 0.22 degree steps, 12 Hz, 360 degrees, 180 mm above the floor.
// Geometry only: the simulated car's node publishes it as sensor_msgs/LaserScan (REP 117: a beam
// with no return within range_max is +infinity, one nearer than range_min -infinity).
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "eaci/grid/map_frame.hpp"
#include "eaci/grid/segment_walk.hpp"
#include "eaci/random.hpp"
#include "eaci/robot/diff_drive.hpp"

namespace eaci::robot {

struct LaserSpec {
  double range_min = 0.1;                      // m
  double range_max = 30.0;                     // m
  double angle_min = -kPi;                     // rad, the first beam, counter-clockwise from the sensor's heading
  double angle_increment = 0.22 * kPi / 180.0; // rad between beams
  int beams = 1636;                            // 360 degrees / 0.22
  double range_sigma = 0.015;                  // m, the noise's standard deviation: +-3 cm read as two of them
  double scan_rate = 12.0;                     // Hz
  double mount_height = 0.18;                  // m above the floor (the frame's z)
  std::uint64_t seed = 1;
};

// The one place a LaserSpec is checked. Returns "" when valid, else a sentence naming the field.
inline std::string validationError(const LaserSpec& s) {
  std::ostringstream e;
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!finite(s.range_min) || s.range_min < 0)
    e << "range_min must be a number >= 0 m (got " << s.range_min << ")";
  else if (!finite(s.range_max) || s.range_max <= s.range_min)
    e << "range_max must be a number above range_min, " << s.range_min << " m (got " << s.range_max << ")";
  else if (!finite(s.angle_min))
    e << "angle_min must be a number (got " << s.angle_min << ")";
  else if (!finite(s.angle_increment) || s.angle_increment <= 0)
    e << "angle_increment must be a number > 0 rad (got " << s.angle_increment << ")";
  else if (s.beams < 1 || s.beams > 100000)
    e << "beams must be in 1..100000 (got " << s.beams << ")";
  else if (!finite(s.range_sigma) || s.range_sigma < 0)
    e << "range_sigma must be a number >= 0 m (got " << s.range_sigma << ")";
  else if (!finite(s.scan_rate) || s.scan_rate <= 0)
    e << "scan_rate must be a number > 0 Hz (got " << s.scan_rate << ")";
  else if (!finite(s.mount_height))
    e << "mount_height must be a number (got " << s.mount_height << ")";
  return e.str();
}

// The distance from `origin` (world, m) along the world angle `angle` to the first cell that
// `blocked(Cell)` calls an obstacle, or +infinity when none lies within `range_max`. The beam
// is walked cell by cell (walkSegment): where it passes exactly through the corner of a blocked
// cell it hits that corner, so no beam slips between two blocked cells that meet diagonally.
// Beyond the map is free space: a beam that leaves it has no return.
template <class Blocked>
double castBeam(const MapFrame& frame, const Blocked& blocked, const Eigen::Vector2d& origin, double angle,
                double range_max) {
  constexpr double kNoReturn = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d end = origin + range_max * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  double travelled = 0.0;  // cells, to the border of the cell being visited
  double hit = kNoReturn;
  bool was_on_map = false;
  walkSegment(frame.worldToPoint(origin), frame.worldToPoint(end), [&](const Cell& c, double length) {
    const bool on_map = c.row >= 0 && c.col >= 0 && c.row < frame.height && c.col < frame.width;
    if (!on_map) return !was_on_map || length == 0.0;  // a straight beam that has left the map never returns
    was_on_map = true;
    if (blocked(c)) {
      hit = travelled * frame.resolution;
      return false;
    }
    travelled += length;
    return true;
  });
  return hit;
}

// One scan from a sensor at `position` facing `yaw` (world): beam k along yaw + angle_min +
// k angle_increment, its range castBeam's plus Gaussian noise of range_sigma when `random` is
// given (none: exact); +infinity beyond range_max, -infinity nearer than range_min (REP 117).
template <class Blocked>
std::vector<float> castScan(const MapFrame& frame, const Blocked& blocked, const Eigen::Vector2d& position, double yaw,
                            const LaserSpec& spec, SplitMix64* random = nullptr) {
  const std::string error = validationError(spec);
  if (!error.empty()) throw std::invalid_argument("laser: " + error);
  std::vector<float> ranges(static_cast<std::size_t>(spec.beams));
  for (int k = 0; k < spec.beams; ++k) {
    const double angle = yaw + spec.angle_min + k * spec.angle_increment;
    double range = castBeam(frame, blocked, position, angle, spec.range_max);
    if (std::isfinite(range) && random != nullptr && spec.range_sigma > 0)
      range += spec.range_sigma * standardNormal(*random);
    if (range > spec.range_max) range = std::numeric_limits<double>::infinity();
    else if (range < spec.range_min) range = -std::numeric_limits<double>::infinity();
    ranges[static_cast<std::size_t>(k)] = static_cast<float>(range);
  }
  return ranges;
}

}  // namespace eaci::robot
