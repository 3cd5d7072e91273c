// The differential-drive kinematics (paper Eq. 5-7, REP 103 signs), exact pose
// integration, wheel limits, and the simulated wheel encoders with their odometry.
// Every expectation is a number worked out by hand from the closed-form kinematics of the
// paper's robot (track B = 0.175 m, wheel radius 0.0325 m), written out, never recomputed
// with the functions under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "eaci/robot/diff_drive.hpp"
#include "eaci/robot/wheel_encoders.hpp"

using namespace eaci::robot;

namespace {
constexpr double kPiTest = 3.14159265358979323846;

Pose2 poseAt(double x, double y, double yaw) { return Pose2{{x, y}, Eigen::Rotation2Dd(yaw)}; }

double distanceBetween(const Pose2& a, const Pose2& b) {
  return std::hypot(a.position.x() - b.position.x(), a.position.y() - b.position.y());
}
}  // namespace

TEST(DiffDrive, StraightMotionHasEqualWheelSpeeds) {
  const WheelSpeeds w = wheelSpeeds(0.2, 0.0, 0.175);
  EXPECT_DOUBLE_EQ(w.left, 0.2);
  EXPECT_DOUBLE_EQ(w.right, 0.2);
  EXPECT_TRUE(std::isinf(turningRadius(w.left, w.right, 0.175)));
}

TEST(DiffDrive, TurningInPlaceCounterClockwise) {
  // omega B / 2 = 1 x 0.175 / 2 = 0.0875 m/s: the wheels turn the opposite ways (v_L = -v_R).
  const WheelSpeeds w = wheelSpeeds(0.0, 1.0, 0.175);  // omega > 0: left turn (REP 103)
  EXPECT_DOUBLE_EQ(w.left, -0.0875);
  EXPECT_DOUBLE_EQ(w.right, 0.0875);
  EXPECT_DOUBLE_EQ(turningRadius(-0.0875, 0.0875, 0.175), 0.0);
}

TEST(DiffDrive, TurningRadiusEq7) {
  // B (v_R + v_L) / (2 (v_R - v_L)) = 0.2 * 0.4 / (2 * 0.2) = 0.2, centre on the left.
  EXPECT_NEAR(turningRadius(0.1, 0.3, 0.2), 0.2, 1e-15);
  // Mirrored wheels: the same radius on the right.
  EXPECT_NEAR(turningRadius(0.3, 0.1, 0.2), -0.2, 1e-15);
}

TEST(DiffDrive, SignConventionAgainstThePaper) {
  // The paper's Eq. 6 omega = (v_L - v_R)/B: v_L = 0.3, v_R = 0.1, B = 0.2 is its +1 rad/s
  // (a right turn, left wheel outer); here it is -1 rad/s (clockwise), v = 0.2 either way.
  const BodyTwist t = bodyTwist({0.3, 0.1}, 0.2);
  EXPECT_NEAR(t.v, 0.2, 1e-15);
  EXPECT_NEAR(t.omega, -1.0, 1e-15);
}

TEST(DiffDrive, WheelSpeedsOfAnArcOnThePapersRobot) {
  // v = 0.3 m/s, omega = 0.5 rad/s on B = 0.175 m: omega B / 2 = 0.04375, so
  // v_L = 0.3 - 0.04375 = 0.25625 and v_R = 0.3 + 0.04375 = 0.34375 m/s; the radius
  // v / omega = 0.6 m, and Eq. 7 gives 0.175 x 0.6 / (2 x 0.0875) = 0.6 m too.
  const WheelSpeeds w = wheelSpeeds(0.3, 0.5, 0.175);
  EXPECT_NEAR(w.left, 0.25625, 1e-15);
  EXPECT_NEAR(w.right, 0.34375, 1e-15);
  const BodyTwist t = bodyTwist({0.25625, 0.34375}, 0.175);
  EXPECT_NEAR(t.v, 0.3, 1e-15);
  EXPECT_NEAR(t.omega, 0.5, 1e-14);
  EXPECT_NEAR(turningRadius(0.25625, 0.34375, 0.175), 0.6, 1e-14);
  // Backwards on the same arc: both wheels negated, v = -0.3, omega = -0.5.
  const BodyTwist back = bodyTwist({-0.25625, -0.34375}, 0.175);
  EXPECT_NEAR(back.v, -0.3, 1e-15);
  EXPECT_NEAR(back.omega, -0.5, 1e-14);
}

TEST(DiffDrive, IntegratesAQuarterCircleExactly) {
  // Radius v/omega = 1 about (0, 1): from (0, 0) facing +x to (1, 1) facing +y.
  const Pose2 end = integrate(poseAt(0.0, 0.0, 0.0), 1.0, 1.0, kPiTest / 2);
  EXPECT_NEAR(end.position.x(), 1.0, 1e-12);
  EXPECT_NEAR(end.position.y(), 1.0, 1e-12);
  EXPECT_NEAR(end.orientation.angle(), kPiTest / 2, 1e-12);
  // A clockwise quarter circle of radius 0.5 from (0, 0): to (0.5, -0.5) facing -y.
  const Pose2 cw = integrate(poseAt(0.0, 0.0, 0.0), 0.5, -1.0, kPiTest / 2);
  EXPECT_NEAR(cw.position.x(), 0.5, 1e-12);
  EXPECT_NEAR(cw.position.y(), -0.5, 1e-12);
  EXPECT_NEAR(cw.orientation.angle(), -kPiTest / 2, 1e-12);
}

TEST(DiffDrive, ACircleOfRadiusVOverOmegaClosesAfterTwoPiOverOmega) {
  // v = 0.3 m/s, omega = 0.5 rad/s from (0, 0) facing +x: a circle of radius 0.6 m about
  // (0, 0.6). After pi s (a quarter) at (0.6, 0.6) facing +y, after 2 pi s at (0, 1.2) facing
  // -x, after 2 pi / omega = 4 pi s back at the start; in one step or in 1000 small ones.
  const Pose2 quarter = integrate(poseAt(0.0, 0.0, 0.0), 0.3, 0.5, kPiTest);
  EXPECT_NEAR(quarter.position.x(), 0.6, 1e-12);
  EXPECT_NEAR(quarter.position.y(), 0.6, 1e-12);
  EXPECT_NEAR(quarter.orientation.angle(), kPiTest / 2, 1e-12);
  const Pose2 half = integrate(poseAt(0.0, 0.0, 0.0), 0.3, 0.5, 2 * kPiTest);
  EXPECT_NEAR(half.position.x(), 0.0, 1e-12);
  EXPECT_NEAR(half.position.y(), 1.2, 1e-12);
  EXPECT_NEAR(std::abs(half.orientation.angle()), kPiTest, 1e-12);
  Pose2 pose = poseAt(0.0, 0.0, 0.0);
  for (int k = 0; k < 1000; ++k) pose = integrate(pose, 0.3, 0.5, 4 * kPiTest / 1000);
  EXPECT_NEAR(pose.position.x(), 0.0, 1e-9);
  EXPECT_NEAR(pose.position.y(), 0.0, 1e-9);
  EXPECT_NEAR(std::sin(pose.orientation.angle()), 0.0, 1e-9);
  EXPECT_GT(std::cos(pose.orientation.angle()), 0.0);
}

TEST(DiffDrive, SmallStepsFollowTheCircleFromAnyPose) {
  // From (0.3, -0.2) at yaw 0.5 with v = 0.4, omega = 0.8: radius 0.5 about
  // (0.3 - 0.5 sin 0.5, -0.2 + 0.5 cos 0.5) = (0.0602872, 0.2387913); after 3 s the yaw is
  // 0.5 + 2.4 = 2.9 and the robot at (0.0602872 + 0.5 sin 2.9, 0.2387913 - 0.5 cos 2.9)
  // = (0.1799119, 0.7242704).
  Pose2 pose = poseAt(0.3, -0.2, 0.5);
  for (int k = 0; k < 100; ++k) pose = integrate(pose, 0.4, 0.8, 0.03);
  EXPECT_NEAR(pose.position.x(), 0.1799119, 1e-7);
  EXPECT_NEAR(pose.position.y(), 0.7242704, 1e-7);
  EXPECT_NEAR(pose.orientation.angle(), 2.9, 1e-12);
}

TEST(DiffDrive, IntegratesAStraightLine) {
  // 0.2 m/s for 5 s along +x: 1 m.
  const Pose2 along_x = integrate(poseAt(0.0, 0.0, 0.0), 0.2, 0.0, 5.0);
  EXPECT_NEAR(along_x.position.x(), 1.0, 1e-15);
  EXPECT_NEAR(along_x.position.y(), 0.0, 1e-15);
  const Pose2 end = integrate(poseAt(1.0, 2.0, kPiTest / 4), 0.5, 0.0, 2.0);  // 1 m at 45 degrees
  EXPECT_NEAR(end.position.x(), 1.0 + std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(end.position.y(), 2.0 + std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(end.orientation.angle(), kPiTest / 4, 1e-15);
}

TEST(DiffDrive, YawIsNormalisedToHalfOpenPiInterval) {
  EXPECT_DOUBLE_EQ(normalizeAngle(-kPiTest), kPiTest);
  EXPECT_DOUBLE_EQ(normalizeAngle(kPiTest), kPiTest);
  EXPECT_NEAR(normalizeAngle(3 * kPiTest), kPiTest, 1e-12);
  EXPECT_NEAR(normalizeAngle(-kPiTest / 2 - 4 * kPiTest), -kPiTest / 2, 1e-12);
  const Pose2 end = integrate(poseAt(0.0, 0.0, 3.0), 0.0, 1.0, 1.0);  // yaw 4 rad = 4 - 2 pi
  EXPECT_NEAR(end.orientation.angle(), 4.0 - 2 * kPiTest, 1e-12);
  EXPECT_DOUBLE_EQ(end.position.x(), 0.0);  // in place: v = 0
  EXPECT_DOUBLE_EQ(end.position.y(), 0.0);
}

TEST(DiffDrive, SaturationKeepsTheTurningRadius) {
  const double b = 0.175;
  const WheelSpeeds w = saturateWheelSpeeds({0.2, 1.0}, 0.5);  // factor 0.5
  EXPECT_DOUBLE_EQ(w.left, 0.1);
  EXPECT_DOUBLE_EQ(w.right, 0.5);
  // Eq. 7 before and after: 0.175 x 1.2 / (2 x 0.8) = 0.175 x 0.6 / (2 x 0.4) = 0.13125 m.
  EXPECT_NEAR(turningRadius(0.2, 1.0, b), 0.13125, 1e-15);
  EXPECT_NEAR(turningRadius(w.left, w.right, b), 0.13125, 1e-15);
  const WheelSpeeds slow = saturateWheelSpeeds({-0.3, 0.4}, 0.5);
  EXPECT_DOUBLE_EQ(slow.left, -0.3);
  EXPECT_DOUBLE_EQ(slow.right, 0.4);
  const WheelSpeeds reverse = saturateWheelSpeeds({-1.0, -0.5}, 0.5);
  EXPECT_DOUBLE_EQ(reverse.left, -0.5);
  EXPECT_DOUBLE_EQ(reverse.right, -0.25);
  const WheelSpeeds bad = saturateWheelSpeeds({std::nan(""), 0.1}, 0.5);
  EXPECT_EQ(bad.left, 0.0);
  EXPECT_EQ(bad.right, 0.0);
}

TEST(DiffDrive, AccelerationLimitScalesTheChange) {
  // 2 m/s^2 over 20 ms allows 0.04 m/s; the larger change (0.5) is cut to 0.04, the
  // other (0.25) by the same factor to 0.02.
  const WheelSpeeds w = limitWheelAcceleration({0.0, 0.0}, {0.25, 0.5}, 2.0, 0.02);
  EXPECT_NEAR(w.left, 0.02, 1e-15);
  EXPECT_NEAR(w.right, 0.04, 1e-15);
  const WheelSpeeds free = limitWheelAcceleration({0.0, 0.0}, {0.25, 0.5}, 0.0, 0.02);
  EXPECT_DOUBLE_EQ(free.right, 0.5);
  const double unlimited = std::numeric_limits<double>::infinity();
  const WheelSpeeds inf = limitWheelAcceleration({0.0, 0.0}, {0.25, 0.5}, unlimited, 0.02);
  EXPECT_DOUBLE_EQ(inf.left, 0.25);
}

TEST(DiffDrive, SimulatedRobotAppliesLimitsAndCountsWheelRotation) {
  DiffDriveParams p;
  p.max_wheel_accel = 0.0;  // unlimited
  DiffDriveRobot robot(p);
  const BodyTwist executed = robot.step(1.0, 0.0, 0.1);  // asks 1 m/s, wheels give 0.5
  EXPECT_DOUBLE_EQ(executed.v, 0.5);
  EXPECT_NEAR(robot.pose().position.x(), 0.05, 1e-15);
  EXPECT_NEAR(robot.leftWheelAngle(), 1.5384615, 1e-7);  // 0.05 m on a 0.0325 m wheel, rad
  EXPECT_NEAR(robot.rightWheelAngle(), 1.5384615, 1e-7);

  DiffDriveRobot gentle;  // default 2 m/s^2: after one 20 ms step at most 0.04 m/s
  EXPECT_NEAR(gentle.step(0.3, 0.0, 0.02).v, 0.04, 1e-15);
  EXPECT_EQ(gentle.step(std::nan(""), 0.0, 0.02).v, 0.0);  // NaN command: brake to standstill (0.04 -> 0)
}

TEST(DiffDrive, ParamsAreValidatedInOnePlace) {
  EXPECT_EQ(validationError(DiffDriveParams{}), "");
  DiffDriveParams p;
  p.wheel_base = 0.0;
  EXPECT_NE(validationError(p).find("wheel_base"), std::string::npos);
  p = {};
  p.wheel_radius = std::nan("");
  EXPECT_NE(validationError(p).find("wheel_radius"), std::string::npos);
  p = {};
  p.max_wheel_speed = -1.0;
  EXPECT_NE(validationError(p).find("max_wheel_speed"), std::string::npos);
  p = {};
  p.max_wheel_accel = -2.0;
  EXPECT_NE(validationError(p).find("max_wheel_accel"), std::string::npos);
  EXPECT_THROW(DiffDriveRobot{p}, std::invalid_argument);
  p.max_wheel_accel = std::numeric_limits<double>::infinity();
  EXPECT_EQ(validationError(p), "");
}

// ------------------------------------------------------------------ wheel encoders

TEST(WheelEncoders, OneRevolutionIsTicksPerRevolution) {
  WheelEncoders enc;  // 1560 ticks per revolution
  const EncoderTicks emitted = enc.rotate(2 * kPiTest, -2 * kPiTest);
  EXPECT_EQ(emitted.left, 1560);
  EXPECT_EQ(emitted.right, -1560);
  EXPECT_EQ(enc.counts().left, 1560);
  EXPECT_EQ(enc.counts().right, -1560);
}

TEST(WheelEncoders, TinyIncrementsLoseNoTicks) {
  // 15600 updates of a tenth of a tick each (not exact in binary) make one revolution.
  WheelEncoders enc;
  const double tenth_tick = 2 * kPiTest / 15600;
  std::int64_t emitted_left = 0;
  for (int k = 0; k < 15600; ++k) emitted_left += enc.rotate(tenth_tick, -tenth_tick).left;
  EXPECT_EQ(enc.counts().left, 1560);
  EXPECT_EQ(enc.counts().right, -1560);
  EXPECT_EQ(emitted_left, 1560);

  TickAccumulator acc;  // 10 x 0.1 = 0.9999999999999999 in doubles: still one tick
  for (int k = 0; k < 10; ++k) acc.add(0.1);
  EXPECT_EQ(acc.count(), 1);
}

namespace {

// Drives the robot for `duration` s with a constant command in steps of at most dt,
// feeding the encoders the wheels' rotation and the odometry the counts; returns the
// largest position error of the odometry seen so far (metres).
double driveAndTrack(DiffDriveRobot& robot, WheelEncoders& encoders, EncoderOdometry& odometry, double v,
                     double omega, double duration, double max_error = 0.0) {
  const double dt = 0.02;
  for (double left = duration; left > 1e-12; left -= dt) {
    const double h = std::min(dt, left);
    const double left_before = robot.leftWheelAngle();
    const double right_before = robot.rightWheelAngle();
    robot.step(v, omega, h);
    encoders.rotate(robot.leftWheelAngle() - left_before, robot.rightWheelAngle() - right_before);
    const Pose2& odom = odometry.update(encoders.counts());
    max_error = std::max(max_error, distanceBetween(odom, robot.pose()));
  }
  return max_error;
}

struct SquareRun {
  Pose2 truth;
  Pose2 odometry;
  double max_error = 0.0;
};

// A 1 m square: 0.2 m/s straight for 5 s, then a quarter turn in place at 1 rad/s, four times.
SquareRun driveSquare(const EncoderParams& encoder_params) {
  DiffDriveParams p;
  p.max_wheel_accel = 0.0;  // exact square
  DiffDriveRobot robot(p);
  WheelEncoders encoders(encoder_params);
  EncoderOdometry odometry(encoder_params.ticks_per_revolution, p.wheel_radius, p.wheel_base);
  SquareRun run;
  for (int side = 0; side < 4; ++side) {
    run.max_error = driveAndTrack(robot, encoders, odometry, 0.2, 0.0, 5.0, run.max_error);
    run.max_error = driveAndTrack(robot, encoders, odometry, 0.0, 1.0, kPiTest / 2, run.max_error);
  }
  run.truth = robot.pose();
  run.odometry = odometry.pose();
  return run;
}

}  // namespace

TEST(WheelEncoders, NoiseFreeOdometryOfASquareMatchesTheTruth) {
  const SquareRun run = driveSquare(EncoderParams{});
  // The truth closes the square.
  EXPECT_NEAR(run.truth.position.x(), 0.0, 1e-9);
  EXPECT_NEAR(run.truth.position.y(), 0.0, 1e-9);
  EXPECT_NEAR(run.truth.orientation.angle(), 0.0, 1e-9);
  // One tick rolls delta = 2 pi r / 1560 = 2 pi 0.0325 / 1560 = 0.1309 mm. Counts are the
  // floors of the exact tick positions, so each wheel's distance is off by < delta at all
  // times, the yaw (d_R - d_L)/B by < 2 delta / B = 0.2618 / 175 = 1.496 mrad, and the
  // position by at most path length x 2 delta / B + (1 + total turn) delta
  // = 4 m x 1.496 mrad + (1 + 2 pi) x 0.1309 mm = 5.984 + 0.953 = 6.94 mm.
  constexpr double kYawBound = 0.001496;     // rad
  constexpr double kPositionBound = 0.00694;  // m
  EXPECT_LT(run.max_error, kPositionBound);
  EXPECT_LT(distanceBetween(run.odometry, run.truth), kPositionBound);
  EXPECT_LT(std::abs(normalizeAngle(run.odometry.orientation.angle() - run.truth.orientation.angle())), kYawBound);
}

TEST(WheelEncoders, NoiseIsDeterministicPerSeed) {
  EncoderParams noisy;
  noisy.noise_ticks = 2.0;
  noisy.seed = 7;
  const SquareRun a = driveSquare(noisy);
  const SquareRun b = driveSquare(noisy);
  EXPECT_EQ(a.odometry.position.x(), b.odometry.position.x());
  EXPECT_EQ(a.odometry.position.y(), b.odometry.position.y());
  EXPECT_EQ(a.odometry.orientation.angle(), b.odometry.orientation.angle());
  noisy.seed = 8;
  const SquareRun c = driveSquare(noisy);
  EXPECT_GT(distanceBetween(a.odometry, c.odometry), 1e-6);
  // The noise makes a difference to the noise-free run.
  const SquareRun exact = driveSquare(EncoderParams{});
  EXPECT_GT(distanceBetween(a.odometry, exact.odometry), 1e-6);
}

TEST(WheelEncoders, UniformNoiseStaysWithinItsAmplitude) {
  EncoderParams p;
  p.noise = EncoderNoise::kUniform;
  p.noise_ticks = 0.4;
  WheelEncoders enc(p);
  const double ten_ticks = 10 * 2 * kPiTest / 1560;
  int not_ten = 0;
  for (int k = 0; k < 1000; ++k) not_ten += enc.rotate(ten_ticks, 0.0).left != 10;
  // Each update adds 10 +- 0.4 ticks, so 1000 updates give 10000 +- 400 (+1 for the floor).
  EXPECT_GE(enc.counts().left, 9600 - 1);
  EXPECT_LE(enc.counts().left, 10400);
  EXPECT_GT(not_ten, 0);  // some updates gave 9 or 11 ticks
  EXPECT_EQ(enc.counts().right, 0);      // a standing wheel gets no noise
}

TEST(WheelEncoders, ParamsAreValidatedInOnePlace) {
  EXPECT_EQ(validationError(EncoderParams{}), "");
  EncoderParams p;
  p.ticks_per_revolution = 0;
  EXPECT_NE(validationError(p).find("ticks_per_revolution"), std::string::npos);
  EXPECT_THROW(WheelEncoders{p}, std::invalid_argument);
  p = {};
  p.noise_ticks = -1.0;
  EXPECT_NE(validationError(p).find("noise_ticks"), std::string::npos);
  EXPECT_THROW(EncoderOdometry(1560, 0.0, 0.175), std::invalid_argument);
}
