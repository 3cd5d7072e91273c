// A PID controller on an error signal, with an output clamp and an anti-windup clamp
// on the integral. Derivative on error (update() sees only the error): the first
// update after reset() has no derivative term, so a standing error gives no kick.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace eaci::robot {

struct PidParams {
  double kp = 1.0;
  double ki = 0.0;
  double kd = 0.0;
  double output_limit = std::numeric_limits<double>::infinity();    // |output| <= this
  double integral_limit = std::numeric_limits<double>::infinity();  // |integral of e dt| <= this (anti-windup)
};

// The one place PidParams are checked. Returns "" when valid, else a sentence.
inline std::string validationError(const PidParams& p) {
  std::ostringstream e;
  auto gain = [](double g) { return std::isfinite(g) && g >= 0; };
  if (!gain(p.kp)) e << "kp must be a number >= 0 (got " << p.kp << ")";
  else if (!gain(p.ki)) e << "ki must be a number >= 0 (got " << p.ki << ")";
  else if (!gain(p.kd)) e << "kd must be a number >= 0 (got " << p.kd << ")";
  else if (std::isnan(p.output_limit) || p.output_limit <= 0)
    e << "output_limit must be > 0, infinity = unlimited (got " << p.output_limit << ")";
  else if (std::isnan(p.integral_limit) || p.integral_limit < 0)
    e << "integral_limit must be >= 0, infinity = unlimited (got " << p.integral_limit << ")";
  return e.str();
}

inline void validate(const PidParams& p) {
  const std::string error = validationError(p);
  if (!error.empty()) throw std::invalid_argument(error);
}

class Pid {
 public:
  explicit Pid(const PidParams& params = {}) : params_(params) { validate(params_); }

  // u = kp e + ki integral(e dt) + kd de/dt, clamped to +-output_limit. With dt <= 0 (or
  // not finite) only the proportional part is returned and no state changes; a
  // non-finite error counts as 0 and leaves the state untouched.
  double update(double error, double dt) {
    if (!std::isfinite(error)) return clampOutput(params_.ki * integral_);
    if (!(dt > 0.0) || !std::isfinite(dt)) return clampOutput(params_.kp * error);
    const double integral = integral_ + error * dt;
    if (std::isfinite(integral)) integral_ = clampIntegral(integral);
    const double derivative = has_previous_ ? (error - previous_error_) / dt : 0.0;
    previous_error_ = error;
    has_previous_ = true;
    return clampOutput(params_.kp * error + params_.ki * integral_ + params_.kd * derivative);
  }

  void reset() {
    integral_ = 0.0;
    previous_error_ = 0.0;
    has_previous_ = false;
  }

  double integral() const { return integral_; }
  const PidParams& params() const { return params_; }

 private:
  double clampIntegral(double value) const {
    return std::clamp(value, -params_.integral_limit, params_.integral_limit);
  }

  double clampOutput(double value) const {
    if (std::isnan(value)) return 0.0;
    return std::clamp(value, -params_.output_limit, params_.output_limit);
  }

  PidParams params_;
  double integral_ = 0.0;
  double previous_error_ = 0.0;
  bool has_previous_ = false;
};

}  // namespace eaci::robot
