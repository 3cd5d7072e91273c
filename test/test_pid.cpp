// The PID controller: each term against hand-computed values, the clamps, and the
// guards against dt <= 0 and non-finite errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "eaci/robot/pid.hpp"

using eaci::robot::Pid;
using eaci::robot::PidParams;

namespace {
PidParams gains(double kp, double ki, double kd) {
  PidParams p;
  p.kp = kp;
  p.ki = ki;
  p.kd = kd;
  return p;
}
}  // namespace

TEST(Pid, ProportionalOnlyGivesKpTimesError) {
  Pid pid(gains(2.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(pid.update(0.5, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(pid.update(0.5, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(pid.update(-0.25, 0.1), -0.5);
}

TEST(Pid, IntegralAccumulatesErrorTimesDtAndIsClamped) {
  PidParams p = gains(0.0, 2.0, 0.0);
  p.integral_limit = 0.25;  // on the integral of e dt: the I term is at most 2 x 0.25 = 0.5
  Pid pid(p);
  EXPECT_NEAR(pid.update(1.0, 0.1), 0.2, 1e-12);  // integral 0.1
  EXPECT_NEAR(pid.update(1.0, 0.1), 0.4, 1e-12);  // 0.2
  EXPECT_NEAR(pid.update(1.0, 0.1), 0.5, 1e-12);  // 0.3, clamped to 0.25
  EXPECT_NEAR(pid.update(1.0, 0.1), 0.5, 1e-12);  // still 0.25: no windup
  EXPECT_NEAR(pid.integral(), 0.25, 1e-12);
  EXPECT_NEAR(pid.update(-1.0, 0.1), 0.3, 1e-12);  // 0.25 - 0.1 = 0.15 at once
  pid.reset();
  EXPECT_EQ(pid.integral(), 0.0);
}

TEST(Pid, DerivativeOnAStepOfTheError) {
  Pid pid(gains(0.0, 0.0, 0.5));
  EXPECT_DOUBLE_EQ(pid.update(0.0, 0.1), 0.0);
  EXPECT_NEAR(pid.update(1.0, 0.1), 5.0, 1e-12);  // 0.5 x (1 - 0) / 0.1
  EXPECT_NEAR(pid.update(1.0, 0.1), 0.0, 1e-12);  // error steady again
  EXPECT_NEAR(pid.update(0.8, 0.05), -2.0, 1e-12);  // 0.5 x (0.8 - 1) / 0.05
  pid.reset();
  EXPECT_DOUBLE_EQ(pid.update(1.0, 0.1), 0.0);  // first update after reset: no kick
}

TEST(Pid, AllThreeTermsAddUp) {
  Pid pid(gains(1.0, 0.5, 0.1));
  pid.update(0.2, 0.1);
  // e = 0.4: P 0.4, I 0.5 x (0.02 + 0.04) = 0.03, D 0.1 x (0.4 - 0.2)/0.1 = 0.2.
  EXPECT_NEAR(pid.update(0.4, 0.1), 0.63, 1e-12);
}

TEST(Pid, OutputIsClamped) {
  PidParams p = gains(10.0, 0.0, 0.0);
  p.output_limit = 1.5;
  Pid pid(p);
  EXPECT_DOUBLE_EQ(pid.update(1.0, 0.1), 1.5);
  EXPECT_DOUBLE_EQ(pid.update(-1.0, 0.1), -1.5);
  EXPECT_DOUBLE_EQ(pid.update(0.1, 0.1), 1.0);
}

TEST(Pid, NonPositiveDtGivesTheProportionalPartOnly) {
  Pid pid(gains(2.0, 1.0, 1.0));
  EXPECT_DOUBLE_EQ(pid.update(0.5, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(pid.update(0.5, -0.1), 1.0);
  EXPECT_DOUBLE_EQ(pid.update(0.5, std::nan("")), 1.0);
  EXPECT_DOUBLE_EQ(pid.update(0.5, std::numeric_limits<double>::infinity()), 1.0);
  EXPECT_EQ(pid.integral(), 0.0);  // no state change
  EXPECT_NEAR(pid.update(0.5, 0.1), 1.0 + 0.05 + 0.0, 1e-12);  // first real update: no derivative
}

TEST(Pid, NonFiniteErrorNeverGivesNaN) {
  Pid pid(gains(2.0, 1.0, 1.0));
  pid.update(0.5, 0.1);  // integral 0.05
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NEAR(pid.update(nan, 0.1), 0.05, 1e-12);  // the error counts as 0: only the I term
  EXPECT_NEAR(pid.update(inf, 0.1), 0.05, 1e-12);
  EXPECT_NEAR(pid.update(-inf, 0.0), 0.05, 1e-12);
  EXPECT_NEAR(pid.integral(), 0.05, 1e-12);
  // The state is untouched: the derivative refers to the last finite error, 0.5.
  EXPECT_NEAR(pid.update(0.5, 0.1), 1.0 + 0.1 + 0.0, 1e-12);
}

TEST(Pid, ParamsAreValidatedInOnePlace) {
  EXPECT_EQ(eaci::robot::validationError(PidParams{}), "");
  PidParams p;
  p.kp = -1.0;
  EXPECT_NE(eaci::robot::validationError(p).find("kp"), std::string::npos);
  p = {};
  p.kd = std::nan("");
  EXPECT_NE(eaci::robot::validationError(p).find("kd"), std::string::npos);
  p = {};
  p.output_limit = 0.0;
  EXPECT_NE(eaci::robot::validationError(p).find("output_limit"), std::string::npos);
  EXPECT_THROW(Pid{p}, std::invalid_argument);
  p = {};
  p.integral_limit = -1.0;
  EXPECT_NE(eaci::robot::validationError(p).find("integral_limit"), std::string::npos);
}
