// A PID path follower for the differential-drive robot, in the spirit of the paper's
// DDMR: it turns in place when the target lies far off its heading, otherwise drives
// forward with v from a distance PID and omega from a heading PID.
//
// Target: a carrot point lookahead_distance ahead of the robot's progress along the
// polyline (progress never goes backwards). Corners sharper than
// rotate_in_place_threshold are stops: the carrot never passes the next stop until the
// robot is within waypoint_tolerance of it, so the robot drives to the corner, turns in
// place there and goes on, instead of cutting it. Gentle bends (e.g. the 45-degree steps
// of a grid path) are smoothed by the carrot.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "eaci/robot/diff_drive.hpp"
#include "eaci/robot/pid.hpp"

namespace eaci::robot {

enum class FollowerState { kIdle, kRotating, kDriving, kArrived };

inline const char* toString(FollowerState s) {
  switch (s) {
    case FollowerState::kIdle: return "idle";
    case FollowerState::kRotating: return "rotating";
    case FollowerState::kDriving: return "driving";
    case FollowerState::kArrived: return "arrived";
  }
  return "?";
}

struct FollowerCommand {
  double v = 0.0;      // m/s, never negative
  double omega = 0.0;  // rad/s, > 0 turns left
  FollowerState state = FollowerState::kIdle;
};

struct PathFollowerParams {
  double max_linear_speed = 0.3;                // m/s
  double max_angular_speed = 1.5;               // rad/s
  double lookahead_distance = 0.25;             // m, carrot distance ahead along the path
  double waypoint_tolerance = 0.05;             // m, a corner counts as reached within this
  double goal_tolerance = 0.05;                 // m, to the last point
  double yaw_tolerance = 0.1;                   // rad, final yaw alignment
  double rotate_in_place_threshold = kPi / 4;   // rad, heading error above which the robot turns in place
  bool align_final_yaw = true;                  // turn to the goal yaw, when one is given, after arriving
  PidParams distance_pid{1.5, 0.0, 0.0};        // v from the distance left to the next stop
  PidParams heading_pid{2.0, 0.0, 0.05};        // omega from the heading error to the carrot
};

// The one place PathFollowerParams are checked. Returns "" when valid, else a sentence.
inline std::string validationError(const PathFollowerParams& p) {
  const std::pair<const char*, double> positives[] = {
      {"max_linear_speed", p.max_linear_speed},     {"max_angular_speed", p.max_angular_speed},
      {"lookahead_distance", p.lookahead_distance}, {"waypoint_tolerance", p.waypoint_tolerance},
      {"goal_tolerance", p.goal_tolerance},         {"yaw_tolerance", p.yaw_tolerance}};
  std::ostringstream e;
  for (const auto& [name, value] : positives) {
    if (std::isfinite(value) && value > 0) continue;
    e << name << " must be a positive number (got " << value << ")";
    return e.str();
  }
  if (!(p.rotate_in_place_threshold > 0) || p.rotate_in_place_threshold > kPi)
    e << "rotate_in_place_threshold must be in (0, pi] (got " << p.rotate_in_place_threshold << ")";
  else if (const std::string d = validationError(p.distance_pid); !d.empty()) e << "distance_pid: " << d;
  else if (const std::string h = validationError(p.heading_pid); !h.empty()) e << "heading_pid: " << h;
  return e.str();
}

inline void validate(const PathFollowerParams& p) {
  const std::string error = validationError(p);
  if (!error.empty()) throw std::invalid_argument(error);
}

// Euclidean distance (std::hypot: no overflow or underflow on the way).
inline double distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  return std::hypot(d.x(), d.y());
}

// Bearing of `to` seen from `from`: radians counter-clockwise from +x, in [-pi, pi].
inline double bearing(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector2d d = to - from;
  return std::atan2(d.y(), d.x());
}

// Heading error to `target`: its bearing from the robot minus the robot's yaw, in (-pi, pi].
inline double headingErrorTo(const Pose2& pose, const Eigen::Vector2d& target) {
  if (target - pose.position == Eigen::Vector2d::Zero()) return 0.0;
  return normalizeAngle(bearing(pose.position, target) - pose.orientation.angle());
}

// Turn angle at the middle one of three points, radians in [0, pi].
inline double turnAngle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return std::abs(normalizeAngle(bearing(b, c) - bearing(a, b)));
}

class PathFollower {
 public:
  explicit PathFollower(const PathFollowerParams& params = {})
      : params_(validated(params)), distance_pid_(params.distance_pid), heading_pid_(params.heading_pid) {}

  // New path (odom/map frame) and optional goal yaw; progress and PIDs start afresh.
  // Non-finite points and repeats of the previous point are dropped.
  void setPath(const std::vector<Eigen::Vector2d>& path, std::optional<double> goal_yaw = std::nullopt) {
    clear();
    for (const Eigen::Vector2d& p : path) {
      if (!p.allFinite()) continue;
      if (!path_.empty() && distance(path_.back(), p) < 1e-9) continue;
      arc_.push_back(path_.empty() ? 0.0 : arc_.back() + distance(path_.back(), p));
      path_.push_back(p);
    }
    if (goal_yaw && std::isfinite(*goal_yaw)) goal_yaw_ = normalizeAngle(*goal_yaw);
    markStops();
    if (!path_.empty()) next_stop_ = stopAfter(0);
  }

  void clear() {
    path_.clear();
    arc_.clear();
    stop_.clear();
    goal_yaw_.reset();
    progress_ = 0.0;
    next_stop_ = 0;
    at_goal_position_ = false;
    state_ = FollowerState::kIdle;
    carrot_.setZero();
    distance_pid_.reset();
    heading_pid_.reset();
  }

  // The command for the robot at `pose`, dt seconds after the previous call.
  FollowerCommand compute(const Pose2& pose, double dt) {
    if (path_.empty()) return command(0.0, 0.0, FollowerState::kIdle);
    if (state_ == FollowerState::kArrived) return command(0.0, 0.0, FollowerState::kArrived);
    if (!pose.position.allFinite() || !std::isfinite(pose.orientation.angle())) return {0.0, 0.0, state_};
    const Eigen::Vector2d& here = pose.position;
    if (distance(here, path_.back()) <= params_.goal_tolerance) at_goal_position_ = true;
    if (at_goal_position_) return alignFinalYaw(pose, dt);
    passReachedStops(here);
    advanceProgress(here);
    carrot_ = pointAt(std::min(progress_ + params_.lookahead_distance, arc_[next_stop_]));
    const double heading_error = headingErrorTo(pose, carrot_);
    if (std::abs(heading_error) > params_.rotate_in_place_threshold) return rotate(heading_error, dt);
    const double distance_left = std::max(arc_[next_stop_] - progress_, distance(here, carrot_));
    return drive(heading_error, distance_left, dt);
  }

  FollowerState state() const { return state_; }
  const std::vector<Eigen::Vector2d>& path() const { return path_; }
  std::optional<double> goalYaw() const { return goal_yaw_; }
  double progress() const { return progress_; }          // m along the path, never decreasing
  std::size_t nextStop() const { return next_stop_; }    // index of the next corner (or the goal)
  const Eigen::Vector2d& carrot() const { return carrot_; }     // the last target point
  const PathFollowerParams& params() const { return params_; }

 private:
  static const PathFollowerParams& validated(const PathFollowerParams& params) {
    validate(params);
    return params;
  }

  FollowerCommand command(double v, double omega, FollowerState state) {
    state_ = state;
    return {v, omega, state};
  }

  // A waypoint is a stop when the path turns there by more than the in-place threshold; the
  // last point always is.
  void markStops() {
    stop_.assign(path_.size(), false);
    if (path_.empty()) return;
    for (std::size_t i = 1; i + 1 < path_.size(); ++i)
      stop_[i] = turnAngle(path_[i - 1], path_[i], path_[i + 1]) > params_.rotate_in_place_threshold;
    stop_.back() = true;
  }

  // The first stop at index > i, or the last point.
  std::size_t stopAfter(std::size_t i) const {
    std::size_t k = std::min(i + 1, path_.size() - 1);
    while (!stop_[k]) ++k;
    return k;
  }

  void passReachedStops(const Eigen::Vector2d& here) {
    while (next_stop_ + 1 < path_.size() && distance(here, path_[next_stop_]) <= params_.waypoint_tolerance) {
      progress_ = std::max(progress_, arc_[next_stop_]);
      next_stop_ = stopAfter(next_stop_);
      heading_pid_.reset();
      distance_pid_.reset();
    }
  }

  // Progress moves to the robot's nearest point on the path between the current progress
  // and min(progress + lookahead, next stop): forward only, never past an unreached stop.
  void advanceProgress(const Eigen::Vector2d& here) {
    const double from = progress_;
    const double to = std::min(progress_ + params_.lookahead_distance, arc_[next_stop_]);
    double best_distance = distance(here, pointAt(from));
    for (std::size_t j = 0; j + 1 < path_.size(); ++j) {
      if (arc_[j + 1] < from || arc_[j] > to) continue;
      const double s = std::clamp(projectOnSegment(here, j), from, to);
      const double d = distance(here, pointAt(s));
      if (d < best_distance) {
        best_distance = d;
        progress_ = s;
      }
    }
  }

  // Arc length of the point of segment j nearest to `p`.
  double projectOnSegment(const Eigen::Vector2d& p, std::size_t j) const {
    const Eigen::Vector2d& a = path_[j];
    const Eigen::Vector2d& b = path_[j + 1];
    const double length = arc_[j + 1] - arc_[j];
    const double t = (p - a).dot(b - a) / (length * length);
    return arc_[j] + std::clamp(t, 0.0, 1.0) * length;
  }

  // The point at arc length s along the path (clamped to its ends).
  Eigen::Vector2d pointAt(double s) const {
    if (s <= 0.0 || path_.size() == 1) return path_.front();
    if (s >= arc_.back()) return path_.back();
    const std::size_t j = static_cast<std::size_t>(std::upper_bound(arc_.begin(), arc_.end(), s) - arc_.begin()) - 1;
    const double t = (s - arc_[j]) / (arc_[j + 1] - arc_[j]);
    return path_[j] + t * (path_[j + 1] - path_[j]);
  }

  FollowerCommand rotate(double heading_error, double dt) {
    if (state_ != FollowerState::kRotating) heading_pid_.reset();
    return command(0.0, limitedOmega(heading_pid_.update(heading_error, dt)), FollowerState::kRotating);
  }

  // Forward speed from the distance PID, slowed linearly with the heading error down to 0 at
  // the in-place threshold; omega from the heading PID.
  FollowerCommand drive(double heading_error, double distance_left, double dt) {
    if (state_ != FollowerState::kDriving) {
      heading_pid_.reset();
      distance_pid_.reset();
    }
    const double omega = limitedOmega(heading_pid_.update(heading_error, dt));
    const double speed = std::clamp(distance_pid_.update(distance_left, dt), 0.0, params_.max_linear_speed);
    const double slowdown = std::max(0.0, 1.0 - std::abs(heading_error) / params_.rotate_in_place_threshold);
    return command(speed * slowdown, omega, FollowerState::kDriving);
  }

  // At the last point: turn in place to the goal yaw when asked to, then arrive.
  FollowerCommand alignFinalYaw(const Pose2& pose, double dt) {
    if (!goal_yaw_ || !params_.align_final_yaw) return command(0.0, 0.0, FollowerState::kArrived);
    const double yaw_error = normalizeAngle(*goal_yaw_ - pose.orientation.angle());
    if (std::abs(yaw_error) < params_.yaw_tolerance) return command(0.0, 0.0, FollowerState::kArrived);
    return rotate(yaw_error, dt);
  }

  double limitedOmega(double omega) const {
    return std::clamp(omega, -params_.max_angular_speed, params_.max_angular_speed);
  }

  PathFollowerParams params_;
  Pid distance_pid_;
  Pid heading_pid_;
  std::vector<Eigen::Vector2d> path_;
  std::vector<double> arc_;  // arc length at each waypoint
  std::vector<bool> stop_;   // corners sharper than the in-place threshold, and the goal
  std::optional<double> goal_yaw_;
  double progress_ = 0.0;
  std::size_t next_stop_ = 0;
  bool at_goal_position_ = false;
  FollowerState state_ = FollowerState::kIdle;
  Eigen::Vector2d carrot_ = Eigen::Vector2d::Zero();
};

}  // namespace eaci::robot
