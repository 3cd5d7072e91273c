// The differential-drive robot of the paper (Section 2.2, Eq. 5-7: a WHEELTEC Mini
// car, 265 x 205 mm): wheel speeds <-> body twist, turning radius, wheel limits and
// exact pose integration. No ROS here; the diff_drive_sim node wraps DiffDriveRobot.
//
// Sign convention: REP 103 (x forward, y left, yaw counter-clockwise), so omega > 0
// turns left and the right wheel is then the outer one:
//   v = (v_R + v_L) / 2,   omega = (v_R - v_L) / B,   v_L = v - omega B/2,   v_R = v + omega B/2.
// The paper writes Eq. 6 as omega = (v_L - v_R) / B, i.e. its omega is positive turning
// clockwise (its v_L is the outer wheel): omega_paper = -omega_here. v (Eq. 5) and the
// radius magnitude (Eq. 7) are the same in both conventions; the radius sign here is
// positive when the turning centre lies on the robot's left.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace eaci::robot {

constexpr double kPi = 3.14159265358979323846;

// A planar pose: position in metres, orientation's angle() the yaw in radians,
// counter-clockwise from +x, in (-pi, pi].
struct Pose2 {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  Eigen::Rotation2Dd orientation = Eigen::Rotation2Dd(0.0);
};

// Linear speeds of the wheels' contact points, m/s.
struct WheelSpeeds {
  double left = 0.0;
  double right = 0.0;
};

// Body twist: forward speed v (m/s) and yaw rate omega (rad/s, > 0 turns left).
struct BodyTwist {
  double v = 0.0;
  double omega = 0.0;
};

struct DiffDriveParams {
  double wheel_base = 0.175;     // B, track width between the wheels' contact points, m
  double wheel_radius = 0.0325;  // m
  double max_wheel_speed = 0.5;  // m/s per wheel; infinity = unlimited
  double max_wheel_accel = 2.0;  // m/s^2 per wheel; 0 or infinity = unlimited
};

// The one place DiffDriveParams are checked. Returns "" when valid, else a sentence.
inline std::string validationError(const DiffDriveParams& p) {
  std::ostringstream e;
  if (!std::isfinite(p.wheel_base) || p.wheel_base <= 0)
    e << "wheel_base must be a positive number of metres (got " << p.wheel_base << ")";
  else if (!std::isfinite(p.wheel_radius) || p.wheel_radius <= 0)
    e << "wheel_radius must be a positive number of metres (got " << p.wheel_radius << ")";
  else if (std::isnan(p.max_wheel_speed) || p.max_wheel_speed <= 0)
    e << "max_wheel_speed must be > 0 m/s, infinity = unlimited (got " << p.max_wheel_speed << ")";
  else if (std::isnan(p.max_wheel_accel) || p.max_wheel_accel < 0)
    e << "max_wheel_accel must be >= 0 m/s^2, 0 or infinity = unlimited (got " << p.max_wheel_accel << ")";
  return e.str();
}

inline void validate(const DiffDriveParams& p) {
  const std::string error = validationError(p);
  if (!error.empty()) throw std::invalid_argument(error);
}

// Angle wrapped into (-pi, pi].
inline double normalizeAngle(double angle) {
  if (!std::isfinite(angle)) return angle;
  double a = std::remainder(angle, 2.0 * kPi);  // [-pi, pi]
  if (a <= -kPi) a += 2.0 * kPi;
  return a;
}

// Inverse kinematics (Eq. 5-6 solved for the wheels): v_L = v - omega B/2, v_R = v + omega B/2.
inline WheelSpeeds wheelSpeeds(double v, double omega, double wheel_base) {
  const double half_difference = omega * wheel_base / 2.0;
  return {v - half_difference, v + half_difference};
}

// Forward kinematics: v = (v_R + v_L)/2 (Eq. 5), omega = (v_R - v_L)/B (Eq. 6, REP 103 sign).
inline BodyTwist bodyTwist(const WheelSpeeds& wheels, double wheel_base) {
  return {(wheels.right + wheels.left) / 2.0, (wheels.right - wheels.left) / wheel_base};
}

// Turning radius R = B (v_R + v_L) / (2 (v_R - v_L)) (Eq. 7): signed, > 0 with the centre
// on the left; infinite when v_L == v_R (straight line), 0 when v_L == -v_R (in place).
inline double turningRadius(double v_left, double v_right, double wheel_base) {
  if (v_right == v_left) return std::numeric_limits<double>::infinity();
  return wheel_base * (v_right + v_left) / (2.0 * (v_right - v_left));
}

// Both wheels scaled by one factor so the faster one runs at max_speed: the turning
// radius is kept. Non-finite speeds give a standstill.
inline WheelSpeeds saturateWheelSpeeds(const WheelSpeeds& wheels, double max_speed) {
  if (!std::isfinite(wheels.left) || !std::isfinite(wheels.right)) return {};
  const double fastest = std::max(std::abs(wheels.left), std::abs(wheels.right));
  if (fastest <= max_speed) return wheels;
  const double scale = max_speed / fastest;
  return {wheels.left * scale, wheels.right * scale};
}

// Moves from `current` towards `target` with wheel accelerations at most max_accel over dt;
// the change of both wheels is scaled by one factor. 0 or infinity = unlimited.
inline WheelSpeeds limitWheelAcceleration(const WheelSpeeds& current, const WheelSpeeds& target,
                                          double max_accel, double dt) {
  if (max_accel == 0.0 || std::isinf(max_accel)) return target;
  if (!(dt > 0.0)) return current;
  const double d_left = target.left - current.left;
  const double d_right = target.right - current.right;
  const double largest = std::max(std::abs(d_left), std::abs(d_right));
  const double allowed = max_accel * dt;
  if (largest <= allowed) return target;
  const double scale = allowed / largest;
  return {current.left + d_left * scale, current.right + d_right * scale};
}

// Exact pose after moving with constant (v, omega) for dt: an arc of radius v/omega,
//   x' = x + v/omega (sin(yaw + omega dt) - sin yaw),  y' = y + v/omega (cos yaw - cos(yaw + omega dt)),
// or a straight line when |omega| < 1e-9. Yaw is normalised to (-pi, pi].
inline Pose2 integrate(const Pose2& pose, double v, double omega, double dt) {
  const double yaw = pose.orientation.angle();
  const double yaw_end = yaw + omega * dt;
  Pose2 next;
  if (std::abs(omega) < 1e-9) {
    const double mid = yaw + omega * dt / 2.0;
    next.position = pose.position + v * dt * Eigen::Vector2d(std::cos(mid), std::sin(mid));
  } else {
    const double radius = v / omega;
    next.position =
        pose.position + radius * Eigen::Vector2d(std::sin(yaw_end) - std::sin(yaw), std::cos(yaw) - std::cos(yaw_end));
  }
  next.orientation = Eigen::Rotation2Dd(normalizeAngle(yaw_end));
  return next;
}

// A simulated robot: commands (v, omega) pass the wheel speed and acceleration limits,
// then the wheels run at constant speed for dt. Keeps the wheels' total rotation for
// simulated encoders.
class DiffDriveRobot {
 public:
  explicit DiffDriveRobot(const DiffDriveParams& params = {}, const Pose2& start = {})
      : params_(params), pose_(start) {
    validate(params_);
  }

  // Applies the command for dt seconds; returns the twist actually executed.
  BodyTwist step(double v, double omega, double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) return twist();
    const WheelSpeeds wanted = saturateWheelSpeeds(wheelSpeeds(v, omega, params_.wheel_base),
                                                   params_.max_wheel_speed);
    wheels_ = limitWheelAcceleration(wheels_, wanted, params_.max_wheel_accel, dt);
    left_angle_ += wheels_.left * dt / params_.wheel_radius;
    right_angle_ += wheels_.right * dt / params_.wheel_radius;
    const BodyTwist executed = twist();
    pose_ = integrate(pose_, executed.v, executed.omega, dt);
    return executed;
  }

  // Puts the robot at `pose`, standing; the wheel angles keep counting, like encoders do.
  void reset(const Pose2& pose) {
    pose_ = pose;
    wheels_ = {};
  }

  const Pose2& pose() const { return pose_; }
  const WheelSpeeds& wheels() const { return wheels_; }
  BodyTwist twist() const { return bodyTwist(wheels_, params_.wheel_base); }
  double leftWheelAngle() const { return left_angle_; }    // total rotation, radians
  double rightWheelAngle() const { return right_angle_; }  // total rotation, radians
  const DiffDriveParams& params() const { return params_; }

 private:
  DiffDriveParams params_;
  Pose2 pose_;
  WheelSpeeds wheels_;
  double left_angle_ = 0.0;
  double right_angle_ = 0.0;
};

}  // namespace eaci::robot
