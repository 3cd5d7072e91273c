// The PID path follower in closed loop with the simulated differential-drive robot
// (50 Hz, no ROS), and its edge cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "eaci/robot/diff_drive.hpp"
#include "eaci/robot/path_follower.hpp"

using namespace eaci::robot;

namespace {

constexpr double kPiTest = 3.14159265358979323846;
constexpr double kDt = 0.02;  // 50 Hz

using Eigen::Vector2d;

Pose2 poseAt(double x, double y, double yaw) { return Pose2{{x, y}, Eigen::Rotation2Dd(yaw)}; }

double distanceTo(const Pose2& pose, const Vector2d& p) {
  return std::hypot(pose.position.x() - p.x(), pose.position.y() - p.y());
}

double distanceToSegment(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const double dx = b.x() - a.x();
  const double dy = b.y() - a.y();
  const double t = std::clamp(((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p.x() - (a.x() + t * dx), p.y() - (a.y() + t * dy));
}

double crossTrackError(const Vector2d& p, const std::vector<Vector2d>& path) {
  if (path.size() == 1) return std::hypot(p.x() - path[0].x(), p.y() - path[0].y());
  double best = 1e300;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) best = std::min(best, distanceToSegment(p, path[k], path[k + 1]));
  return best;
}

struct FollowRun {
  bool arrived = false;
  double arrival_time = 0.0;
  Pose2 final_pose;
  double max_cross_track = 0.0;
  double max_v = 0.0;
  double max_abs_omega = 0.0;
  double min_v = 0.0;
  int rotating_in_place_steps = 0;   // Rotating with v == 0
  bool rotated_at_corner = false;    // ... within 0.1 m of `corner`
  bool progress_monotone = true;
  std::vector<FollowerState> states;
};

// Follows `path` from `start` with the default robot (wheel limits and 2 m/s^2) at 50 Hz.
FollowRun follow(const std::vector<Vector2d>& path, const Pose2& start, std::optional<double> goal_yaw = std::nullopt,
           const PathFollowerParams& params = {}, Vector2d corner = {1e9, 1e9}, double time_limit = 20.0) {
  DiffDriveRobot robot(DiffDriveParams{}, start);
  PathFollower follower(params);
  follower.setPath(path, goal_yaw);
  FollowRun run;
  double last_progress = 0.0;
  for (double t = 0.0; t < time_limit; t += kDt) {
    const FollowerCommand cmd = follower.compute(robot.pose(), kDt);
    run.states.push_back(cmd.state);
    run.max_v = std::max(run.max_v, cmd.v);
    run.min_v = std::min(run.min_v, cmd.v);
    run.max_abs_omega = std::max(run.max_abs_omega, std::abs(cmd.omega));
    if (follower.progress() < last_progress) run.progress_monotone = false;
    last_progress = follower.progress();
    if (cmd.state == FollowerState::kRotating && cmd.v == 0.0) {
      ++run.rotating_in_place_steps;
      if (distanceTo(robot.pose(), corner) < 0.1) run.rotated_at_corner = true;
    }
    if (cmd.state == FollowerState::kArrived) {
      run.arrived = true;
      run.arrival_time = t;
      break;
    }
    robot.step(cmd.v, cmd.omega, kDt);
    run.max_cross_track = std::max(run.max_cross_track, crossTrackError(robot.pose().position, path));
  }
  run.final_pose = robot.pose();
  return run;
}

}  // namespace

TEST(PathFollower, FollowsAnLShapedPathTurningInPlaceAtTheCorner) {
  const std::vector<Vector2d> path = {{0, 0}, {1, 0}, {1, 1}};
  const PathFollowerParams params;
  const FollowRun run = follow(path, poseAt(0, 0, 0), std::nullopt, params, {1, 0});
  ASSERT_TRUE(run.arrived);
  // 2 m at 0.3 m/s is 6.7 s; braking into the corner and the goal and a quarter turn add a
  // few seconds: well under 20 s.
  EXPECT_LT(run.arrival_time, 20.0);
  EXPECT_LE(distanceTo(run.final_pose, path.back()), params.goal_tolerance);
  EXPECT_LT(run.max_cross_track, 0.1);
  EXPECT_TRUE(run.rotated_at_corner);
  EXPECT_LE(run.max_v, params.max_linear_speed + 1e-12);
  EXPECT_GE(run.min_v, 0.0);
  EXPECT_LE(run.max_abs_omega, params.max_angular_speed + 1e-12);
  EXPECT_TRUE(run.progress_monotone);
  std::cout << "[ measured ] L path: arrived after " << run.arrival_time << " s, max cross-track "
            << run.max_cross_track * 1000 << " mm, " << run.rotating_in_place_steps << " in-place steps, final error "
            << distanceTo(run.final_pose, path.back()) * 1000 << " mm\n";
}

TEST(PathFollower, APathBehindTheRobotMakesItRotateFirst) {
  const std::vector<Vector2d> path = {{0, 0}, {-1, 0}};
  PathFollower follower;
  follower.setPath(path);
  const FollowerCommand first = follower.compute(poseAt(0, 0, 0), kDt);
  EXPECT_EQ(first.state, FollowerState::kRotating);
  EXPECT_EQ(first.v, 0.0);
  EXPECT_NE(first.omega, 0.0);
  EXPECT_LE(std::abs(first.omega), 1.5);

  const FollowRun run = follow(path, poseAt(0, 0, 0));
  ASSERT_TRUE(run.arrived);
  EXPECT_EQ(run.states.front(), FollowerState::kRotating);
  EXPECT_LE(distanceTo(run.final_pose, path.back()), 0.05);
  EXPECT_NEAR(std::abs(run.final_pose.orientation.angle()), kPiTest, 0.2);  // facing -x
}

TEST(PathFollower, EmptyPathIsIdle) {
  PathFollower follower;
  FollowerCommand cmd = follower.compute(poseAt(0, 0, 0), kDt);
  EXPECT_EQ(cmd.state, FollowerState::kIdle);
  EXPECT_EQ(cmd.v, 0.0);
  EXPECT_EQ(cmd.omega, 0.0);
  follower.setPath({});
  EXPECT_EQ(follower.compute(poseAt(0, 0, 0), kDt).state, FollowerState::kIdle);
  follower.setPath({{1, 0}});
  EXPECT_EQ(follower.compute(poseAt(0, 0, 0), kDt).state, FollowerState::kDriving);
  follower.clear();
  cmd = follower.compute(poseAt(0, 0, 0), kDt);
  EXPECT_EQ(cmd.state, FollowerState::kIdle);
  EXPECT_EQ(cmd.v, 0.0);
}

TEST(PathFollower, StartingAtTheGoalArrivesAtOnce) {
  PathFollower follower;
  follower.setPath({{0, 0}, {1, 0}});
  const FollowerCommand cmd = follower.compute(poseAt(1.03, 0.0, 2.0), kDt);  // 3 cm < goal_tolerance
  EXPECT_EQ(cmd.state, FollowerState::kArrived);
  EXPECT_EQ(cmd.v, 0.0);
  EXPECT_EQ(cmd.omega, 0.0);
  EXPECT_EQ(follower.compute(poseAt(5, 5, 0), kDt).state, FollowerState::kArrived);  // stays until a new path
}

TEST(PathFollower, DrivesToASinglePoint) {
  const std::vector<Vector2d> path = {{1.0, 0.5}};
  const FollowRun run = follow(path, poseAt(0, 0, 0));
  ASSERT_TRUE(run.arrived);
  EXPECT_EQ(run.states.front(), FollowerState::kDriving);  // 26.6 degrees off: below the 45 threshold
  EXPECT_LE(distanceTo(run.final_pose, path[0]), 0.05);
}

TEST(PathFollower, TurnsToTheGoalYawAfterArriving) {
  const std::vector<Vector2d> path = {{0, 0}, {0.6, 0}};
  const FollowRun run = follow(path, poseAt(0, 0, 0), kPiTest / 2);
  ASSERT_TRUE(run.arrived);
  EXPECT_NEAR(run.final_pose.orientation.angle(), kPiTest / 2, 0.1);
  EXPECT_LE(distanceTo(run.final_pose, path.back()), 0.05);
  ASSERT_GE(run.states.size(), 2u);
  EXPECT_EQ(run.states[run.states.size() - 2], FollowerState::kRotating);  // the final turn in place

  PathFollowerParams no_align;
  no_align.align_final_yaw = false;
  const FollowRun plain = follow(path, poseAt(0, 0, 0), kPiTest / 2, no_align);
  ASSERT_TRUE(plain.arrived);
  EXPECT_NEAR(plain.final_pose.orientation.angle(), 0.0, 0.1);  // the goal yaw is ignored
}

TEST(PathFollower, GentleBendsAreDrivenThroughWithoutStopping) {
  // A grid-like path: 45-degree bends are not above the in-place threshold, so no stop.
  const std::vector<Vector2d> path = {{0, 0}, {0.5, 0}, {1.0, 0.5}, {1.5, 0.5}};
  const FollowRun run = follow(path, poseAt(0, 0, 0));
  ASSERT_TRUE(run.arrived);
  EXPECT_EQ(run.rotating_in_place_steps, 0);
  EXPECT_LT(run.max_cross_track, 0.1);
  EXPECT_LE(distanceTo(run.final_pose, path.back()), 0.05);
}

TEST(PathFollower, ParamsAreValidatedInOnePlace) {
  EXPECT_EQ(validationError(PathFollowerParams{}), "");
  PathFollowerParams p;
  p.max_linear_speed = 0.0;
  EXPECT_NE(validationError(p).find("max_linear_speed"), std::string::npos);
  EXPECT_THROW(PathFollower{p}, std::invalid_argument);
  p = {};
  p.lookahead_distance = std::nan("");
  EXPECT_NE(validationError(p).find("lookahead_distance"), std::string::npos);
  p = {};
  p.rotate_in_place_threshold = 4.0;
  EXPECT_NE(validationError(p).find("rotate_in_place_threshold"), std::string::npos);
  p = {};
  p.heading_pid.kp = -1.0;
  EXPECT_NE(validationError(p).find("heading_pid: kp"), std::string::npos);
  const PathFollowerParams d;
  EXPECT_DOUBLE_EQ(d.max_linear_speed, 0.3);
  EXPECT_DOUBLE_EQ(d.max_angular_speed, 1.5);
  EXPECT_DOUBLE_EQ(d.lookahead_distance, 0.25);
  EXPECT_DOUBLE_EQ(d.goal_tolerance, 0.05);
  EXPECT_DOUBLE_EQ(d.yaw_tolerance, 0.1);
  EXPECT_NEAR(d.rotate_in_place_threshold, kPiTest / 4, 1e-15);
}
