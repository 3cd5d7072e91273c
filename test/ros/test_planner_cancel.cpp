// ~cancel on a running eaci_planner_node (see planner_cancel.test): a plan configured for a very
// long run stops soon after ~cancel with the best route found so far, concurrent make_plan calls
// are served one at a time and each can be cancelled, and the node keeps answering.
#include <gtest/gtest.h>
#include <nav_msgs/GetPlan.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <future>
#include <memory>
#include <string>
#include <thread>

#include "eaci/io/map_io.hpp"
#include "map_pose.hpp"
#include "route_check.hpp"

namespace {

using eaci_test::mapPose;

// The long node runs a huge number of iterations with no early stop and no time limit; the
// short node the same map and parameters but few iterations, to time an iteration.
const std::string kLong = "/eaci_planner_node";
const std::string kShort = "/eaci_planner_short";

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Answer {
  bool called = false;
  nav_msgs::Path plan;
  double seconds = 0;
};

// make_plan across the lab (cell centres: a point on a cell edge may fall in either cell, as the
// node reads the resolution as nav_msgs' float32), from another thread. The thread is detached: should the node never
// answer, the test fails on its own bound instead of hanging in a future's destructor.
std::shared_future<Answer> planInBackground(const std::string& node) {
  auto promise = std::make_shared<std::promise<Answer>>();
  std::shared_future<Answer> future = promise->get_future().share();
  std::thread([node, promise] {
    nav_msgs::GetPlan srv;
    srv.request.start = mapPose(0.425, 0.425);
    srv.request.goal = mapPose(4.425, 2.625);
    const auto begin = Clock::now();
    Answer answer;
    answer.called = ros::service::call(node + "/make_plan", srv);
    answer.seconds = secondsSince(begin);
    answer.plan = srv.response.plan;
    promise->set_value(answer);
  }).detach();
  return future;
}

std_srvs::Trigger::Response cancel(const std::string& node) {
  std_srvs::Trigger srv;
  EXPECT_TRUE(ros::service::call(node + "/cancel", srv)) << "the cancel call itself failed";
  return srv.response;
}

bool ready(const std::shared_future<Answer>& f) { return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready; }

class PlannerCancel : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string file;
    ASSERT_TRUE(ros::param::get("~map_file", file));
    map_ = eaci::loadMap(file);
    for (const std::string& node : {kLong, kShort}) {
      ASSERT_TRUE(ros::service::waitForService(node + "/make_plan", ros::Duration(30.0)));
      ASSERT_TRUE(ros::service::waitForService(node + "/cancel", ros::Duration(30.0)));
    }
    ASSERT_TRUE(ros::param::get(kLong + "/max_iterations", long_iterations_));
    ASSERT_TRUE(ros::param::get(kShort + "/max_iterations", short_iterations_));
    ASSERT_GE(long_iterations_, 10000 * short_iterations_);
    // What a full run of the long node would take: the short node's run, scaled.
    const auto timed = planInBackground(kShort);
    ASSERT_EQ(timed.wait_for(std::chrono::seconds(60)), std::future_status::ready);
    ASSERT_TRUE(timed.get().called);
    ASSERT_FALSE(timed.get().plan.poses.empty());
    full_run_seconds_ = timed.get().seconds * long_iterations_ / short_iterations_;
  }

  void expectValidRoute(const nav_msgs::Path& path) {
    const auto start = map_.worldToCell({0.425, 0.425}), goal = map_.worldToCell({4.425, 2.625});
    EXPECT_EQ(eaci_test::routeDefect(map_, path, *start, *goal), "");
  }

  // Cancels every 0.2 s until `plan` returns; false if it has not after `limit` seconds.
  bool cancelUntilAnswered(const std::shared_future<Answer>& plan, double limit, int* accepted) {
    const auto begin = Clock::now();
    while (!ready(plan)) {
      if (secondsSince(begin) > limit) return false;
      if (cancel(kLong).success) ++*accepted;
      plan.wait_for(std::chrono::milliseconds(200));
    }
    return true;
  }

  eaci::OccupancyMap map_;
  int long_iterations_ = 0, short_iterations_ = 0;
  double full_run_seconds_ = 0;
};

}  // namespace

TEST_F(PlannerCancel, WithoutAPlanInProgressCancelSaysSo) {
  const auto response = cancel(kLong);
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("no plan in progress"), std::string::npos) << response.message;
}

TEST_F(PlannerCancel, CancelStopsTheRunningPlanSoonWithTheBestRouteSoFar) {
  const auto plan = planInBackground(kLong);
  std::this_thread::sleep_for(std::chrono::seconds(2));  // long enough for the ants to reach the goal
  ASSERT_FALSE(ready(plan)) << "the long plan ended by itself";
  int accepted = 0;
  // A twentieth of the configured run: far beyond the 2 s before the cancel, far below a full run.
  const double bound = full_run_seconds_ / 20;
  ASSERT_TRUE(cancelUntilAnswered(plan, bound, &accepted))
      << "make_plan still running " << bound << " s after ~cancel; a full run of " << long_iterations_
      << " iterations would take about " << full_run_seconds_ << " s";
  EXPECT_GE(accepted, 1);
  const Answer answer = plan.get();
  ASSERT_TRUE(answer.called);
  std::printf("planner cancel: make_plan returned after %.2f s (cancelled at 2 s); a full run of %d iterations "
              "would take about %.0f s (%d iterations took %.3f s)\n",
              answer.seconds, long_iterations_, full_run_seconds_, short_iterations_,
              full_run_seconds_ * short_iterations_ / long_iterations_);
  EXPECT_LT(answer.seconds, 2.0 + bound);
  ASSERT_FALSE(answer.plan.poses.empty()) << "no best route so far after 2 s on the lab map";
  expectValidRoute(answer.plan);
  // The next plan is not affected by the old cancel, and a cancel now finds nothing to stop.
  const auto late = cancel(kLong);
  EXPECT_FALSE(late.success);
  EXPECT_NE(late.message.find("no plan in progress"), std::string::npos) << late.message;
}

TEST_F(PlannerCancel, ConcurrentPlansRunOneAtATimeAndEachCanBeCancelled) {
  const auto first = planInBackground(kLong);
  const auto second = planInBackground(kLong);
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_FALSE(ready(first) || ready(second));
  int accepted = 0;
  const double bound = full_run_seconds_ / 20;
  // One of them is planning, the other waits for it; a cancel reaches only the plan in progress.
  const auto begin = Clock::now();
  while (!ready(first) && !ready(second)) {
    ASSERT_LT(secondsSince(begin), bound);
    if (cancel(kLong).success) ++accepted;
    first.wait_for(std::chrono::milliseconds(200));
  }
  EXPECT_GE(accepted, 1);
  ASSERT_FALSE(ready(first) && ready(second)) << "one cancel ended both plans";
  const auto& done = ready(first) ? first : second;
  const auto& waiting = ready(first) ? second : first;
  // The other one starts now and runs until it is cancelled in turn.
  std::this_thread::sleep_for(std::chrono::seconds(2));
  ASSERT_FALSE(ready(waiting)) << "the second plan ended without a cancel";
  ASSERT_TRUE(cancelUntilAnswered(waiting, bound, &accepted));
  EXPECT_GE(accepted, 2);
  EXPECT_GT(waiting.get().seconds, done.get().seconds + 1.5);  // it waited for the first one
  for (const auto* plan : {&first, &second}) {
    const Answer answer = plan->get();
    ASSERT_TRUE(answer.called);
    ASSERT_FALSE(answer.plan.poses.empty());
    expectValidRoute(answer.plan);
  }
  // Still answering.
  const auto after = planInBackground(kShort);
  ASSERT_EQ(after.wait_for(std::chrono::seconds(60)), std::future_status::ready);
  EXPECT_FALSE(after.get().plan.poses.empty());
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_planner_cancel");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
