// Talks to a running eaci_planner_node (see planner_node.test) through its make_plan service.
#include <gtest/gtest.h>
#include <nav_msgs/GetPlan.h>
#include <ros/ros.h>

#include <cmath>
#include <initializer_list>
#include <string>

#include "eaci/io/map_io.hpp"
#include "map_pose.hpp"
#include "node_log.hpp"

namespace {

using eaci_test::mapPose;

const char* kService = "/eaci_planner_node/make_plan";

nav_msgs::GetPlan::Response plan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                                 double tolerance = 0.0) {
  nav_msgs::GetPlan srv;
  srv.request.start = start;
  srv.request.goal = goal;
  srv.request.tolerance = static_cast<float>(tolerance);
  EXPECT_TRUE(ros::service::call(kService, srv)) << "the service call itself failed";
  return srv.response;
}

class PlannerNode : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string file;
    ASSERT_TRUE(ros::param::get("~map_file", file));
    map_ = eaci::loadMap(file);
    ASSERT_TRUE(ros::service::waitForService(kService, ros::Duration(30.0)));
    // The node's log lines reach only a connected subscriber: ask for a goal off the map until
    // its warning arrives.
    bool connected = false;
    for (int k = 0; k < 50 && !connected; ++k) {
      plan(mapPose(0.4, 0.4), mapPose(10.0, 10.0));
      connected = !log_.waitFor({"no plan (goal_off_map)"}, 0.2).empty();
    }
    ASSERT_TRUE(connected) << "no warning of eaci_planner_node on /rosout";
  }

  // The request gets an empty plan and the node says why: a warning or error of its own that
  // holds every one of `parts`.
  void expectRefusedWith(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                         std::initializer_list<std::string> parts) {
    log_.clear();
    EXPECT_TRUE(plan(start, goal).plan.poses.empty()) << "planned a request that must fail";
    std::string wanted;
    for (const std::string& part : parts) wanted += " '" + part + "'";
    EXPECT_NE(log_.waitFor(parts), "") << "no line of the node holds" << wanted << "; it said:" << log_.seen();
  }

  bool freeAt(double x, double y) const {
    const auto cell = map_.worldToCell({x, y});
    return cell && map_.cells[static_cast<std::size_t>(cell->row) * map_.width + cell->col] == eaci::kFreeValue;
  }

  eaci::OccupancyMap map_;
  eaci_test::NodeLog log_{"/eaci_planner_node"};
};

}  // namespace

TEST_F(PlannerNode, PlansACollisionFreeRouteAcrossTheLab) {
  const auto response = plan(mapPose(0.4, 0.4), mapPose(4.4, 2.6));
  const auto& poses = response.plan.poses;
  ASSERT_GE(poses.size(), 2u);
  EXPECT_EQ(response.plan.header.frame_id, "map");
  EXPECT_NEAR(poses.front().pose.position.x, 0.4, 1e-6);
  EXPECT_NEAR(poses.back().pose.position.y, 2.6, 1e-6);
  double length = 0.0;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const auto& p = poses[k].pose.position;
    EXPECT_TRUE(freeAt(p.x, p.y)) << "pose " << k << " (" << p.x << ", " << p.y << ") is not on a free cell";
    if (k == 0) continue;
    const auto& q = poses[k - 1].pose.position;
    const double step = std::hypot(p.x - q.x, p.y - q.y);
    // Neighbouring cell centres, except that the first and last poses are the request's own
    // start and goal, anywhere in their cells.
    const bool end = k == 1 || k + 1 == poses.size();
    EXPECT_LE(step, map_.resolution * std::sqrt(2.0) * (end ? 1.5 : 1.0) + 1e-6) << "gap before pose " << k;
    length += step;
  }
  // The straight line is 4.47 m; the U-shaped obstacle lies across it.
  EXPECT_GT(length, std::hypot(4.0, 2.2));
  EXPECT_LT(length, 1.2 * 4.9113);  // A* optimum on this map: 98.2254 cells = 4.9113 m
}

// Each bad request fails for its own reason: the node's line holds the outcome's word ("no plan
// (goal_blocked)", PlanOutcome) and the sentence (src/service/planning_service.cpp and
// src/ros/ros_planner.cpp word them; positions with up to three decimals, eaci::formatNumber).
TEST_F(PlannerNode, BadRequestsGetAnEmptyPlanNamingTheirFaultAndTheNodeStaysUp) {
  // Goal in the border wall (the map's bottom-left cell), no tolerance.
  EXPECT_FALSE(freeAt(0.025, 0.025));
  expectRefusedWith(mapPose(0.4, 0.4), mapPose(0.025, 0.025),
                    {"no plan (goal_blocked)", "goal (0.025, 0.025) is in an obstacle"});
  // Start in the wall.
  EXPECT_FALSE(freeAt(0.025, 1.0));
  expectRefusedWith(mapPose(0.025, 1.0), mapPose(4.4, 2.6), {"no plan (start_blocked)", "start (0.025, 1)"});
  // Off the map (4.8 x 3.0 m from the origin).
  expectRefusedWith(mapPose(0.4, 0.4), mapPose(10.0, 10.0), {"no plan (goal_off_map)", "goal (10, 10)"});
  expectRefusedWith(mapPose(-1.0, 0.4), mapPose(4.4, 2.6), {"no plan (start_off_map)", "start (-1, 0.4)"});
  // A frame nobody publishes.
  expectRefusedWith(mapPose(0.4, 0.4, "nowhere"), mapPose(4.4, 2.6),
                    {"no plan (start_off_map)", "the start is in frame 'nowhere', the costmap in 'map'", "cannot be transformed"});
  expectRefusedWith(mapPose(0.4, 0.4), mapPose(4.4, 2.6, "nowhere"),
                    {"no plan (goal_off_map)", "the goal is in frame 'nowhere', the costmap in 'map'", "cannot be transformed"});
  // NaN: no cell holds it.
  expectRefusedWith(mapPose(std::nan(""), 0.4), mapPose(4.4, 2.6), {"no plan (start_off_map)", "nan, 0.4)"});
  // Still answering.
  EXPECT_FALSE(plan(mapPose(0.4, 0.4), mapPose(4.4, 2.6)).plan.poses.empty());
}

TEST_F(PlannerNode, GoalInAnObstacleMovesToTheNearestFreeCellWithinTolerance) {
  // (0.025, 1.5): a border-wall cell one cell from free space.
  EXPECT_FALSE(freeAt(0.025, 1.5));
  const auto response = plan(mapPose(0.4, 0.4), mapPose(0.025, 1.5), 0.2);
  ASSERT_FALSE(response.plan.poses.empty());
  const auto& last = response.plan.poses.back().pose.position;
  EXPECT_TRUE(freeAt(last.x, last.y));
  EXPECT_LE(std::hypot(last.x - 0.025, last.y - 1.5), 0.2 + 1e-6);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_planner_node");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);  // /rosout lines for NodeLog
  spinner.start();
  return RUN_ALL_TESTS();
}
