// Simulated wheel encoders (integer ticks from the wheels' true rotation, optional
// noise, deterministic per seed) and dead-reckoning odometry from tick counts.
#pragma once

#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "eaci/random.hpp"
#include "eaci/robot/diff_drive.hpp"

namespace eaci::robot {

enum class EncoderNoise {
  kGaussian,  // noise_ticks is the standard deviation
  kUniform,   // noise_ticks is the amplitude: uniform in [-noise_ticks, noise_ticks]
};

struct EncoderParams {
  int ticks_per_revolution = 1560;  // e.g. a 13-line Hall encoder x4 on a 1:30 gear motor
  double noise_ticks = 0.0;         // noise per update and moving wheel, ticks; 0 = exact
  EncoderNoise noise = EncoderNoise::kGaussian;
  std::uint64_t seed = 1;
};

// The one place EncoderParams are checked. Returns "" when valid, else a sentence.
inline std::string validationError(const EncoderParams& p) {
  std::ostringstream e;
  if (p.ticks_per_revolution < 1)
    e << "ticks_per_revolution must be >= 1 (got " << p.ticks_per_revolution << ")";
  else if (!std::isfinite(p.noise_ticks) || p.noise_ticks < 0)
    e << "noise_ticks must be a number >= 0 (got " << p.noise_ticks << ")";
  return e.str();
}

inline void validate(const EncoderParams& p) {
  const std::string error = validationError(p);
  if (!error.empty()) throw std::invalid_argument(error);
}

struct EncoderTicks {
  std::int64_t left = 0;
  std::int64_t right = 0;
};

// Distance rolled by a wheel for `ticks` ticks: ticks 2 pi r / ticks_per_revolution.
inline double ticksToDistance(double ticks, int ticks_per_revolution, double wheel_radius) {
  return ticks * 2.0 * kPi * wheel_radius / ticks_per_revolution;
}

// Ticks for a wheel rotation of `radians`: radians / (2 pi) ticks_per_revolution.
inline double radiansToTicks(double radians, int ticks_per_revolution) {
  return radians / (2.0 * kPi) * ticks_per_revolution;
}

// One wheel's counter: whole ticks are emitted, the fraction is kept for later, so
// no tick is ever lost however small the increments. A 1e-9 tick slack absorbs the
// rounding of sums such as 10 x 0.1.
class TickAccumulator {
 public:
  // Adds `ticks` (any real number, signed); returns the whole ticks emitted.
  std::int64_t add(double ticks) {
    if (!std::isfinite(ticks)) return 0;
    fraction_ += ticks;
    const double whole = std::floor(fraction_ + kSlack);
    fraction_ -= whole;
    const auto emitted = static_cast<std::int64_t>(whole);
    count_ += emitted;
    return emitted;
  }

  std::int64_t count() const { return count_; }
  double fraction() const { return fraction_; }

 private:
  static constexpr double kSlack = 1e-9;
  std::int64_t count_ = 0;
  double fraction_ = 0.0;
};

// The two encoders of a differential-drive robot.
class WheelEncoders {
 public:
  explicit WheelEncoders(const EncoderParams& params = {}) : params_(params), rng_(params.seed) {
    validate(params_);
  }

  // The wheels turned by these angles (radians, signed) since the last update;
  // returns the ticks emitted by this update. A standing wheel gets no noise.
  EncoderTicks rotate(double left_radians, double right_radians) {
    const double left = radiansToTicks(left_radians, params_.ticks_per_revolution);
    const double right = radiansToTicks(right_radians, params_.ticks_per_revolution);
    return {left_.add(withNoise(left)), right_.add(withNoise(right))};
  }

  EncoderTicks counts() const { return {left_.count(), right_.count()}; }
  const EncoderParams& params() const { return params_; }

 private:
  double withNoise(double ticks) {
    if (params_.noise_ticks == 0.0 || ticks == 0.0) return ticks;
    return ticks + params_.noise_ticks * unitNoise();
  }

  // Standard normal (Box-Muller from two uniforms) or uniform in [-1, 1].
  double unitNoise() {
    if (params_.noise == EncoderNoise::kUniform) return 2.0 * rng_.uniform() - 1.0;
    return standardNormal(rng_);
  }

  EncoderParams params_;
  SplitMix64 rng_;
  TickAccumulator left_;
  TickAccumulator right_;
};

// Dead reckoning from encoder counts: each update turns the tick deltas into wheel
// distances d_L, d_R, then moves along the arc of v dt = (d_R + d_L)/2 and
// omega dt = (d_R - d_L)/B (Eq. 5-6 over one update), integrated exactly.
class EncoderOdometry {
 public:
  EncoderOdometry(int ticks_per_revolution, double wheel_radius, double wheel_base)
      : ticks_per_revolution_(ticks_per_revolution), wheel_radius_(wheel_radius), wheel_base_(wheel_base) {
    auto positive = [](double v) { return std::isfinite(v) && v > 0; };
    if (ticks_per_revolution < 1 || !positive(wheel_radius) || !positive(wheel_base))
      throw std::invalid_argument("EncoderOdometry needs ticks >= 1 per revolution and a positive wheel radius and base");
  }

  // Starts again from `pose`, with `counts` as the reference for the next deltas.
  void reset(const Pose2& pose, const EncoderTicks& counts = {}) {
    pose_ = pose;
    last_ = counts;
    distance_ = rotation_ = 0.0;
  }

  // New absolute counts in; the updated pose out.
  const Pose2& update(const EncoderTicks& counts) {
    const double d_left = wheelDistance(counts.left - last_.left);
    const double d_right = wheelDistance(counts.right - last_.right);
    last_ = counts;
    distance_ = (d_right + d_left) / 2.0;
    rotation_ = (d_right - d_left) / wheel_base_;
    pose_ = integrate(pose_, distance_, rotation_, 1.0);
    return pose_;
  }

  const Pose2& pose() const { return pose_; }
  double lastDistance() const { return distance_; }  // m moved by the last update (divide by dt for v)
  double lastRotation() const { return rotation_; }  // rad turned by the last update (divide by dt for omega)

 private:
  double wheelDistance(std::int64_t ticks) const {
    return ticksToDistance(static_cast<double>(ticks), ticks_per_revolution_, wheel_radius_);
  }

  int ticks_per_revolution_;
  double wheel_radius_;
  double wheel_base_;
  Pose2 pose_;
  EncoderTicks last_;
  double distance_ = 0.0;
  double rotation_ = 0.0;
};

}  // namespace eaci::robot
