// A map that changes under eaci_planner_node (see planner_map_change.test): the node plans on
// the `map` topic, and the test publishes maps that grow, move and change between requests, as
// a SLAM map or a rolling window does, and one while a plan is running. Every answer must be a
// valid route on the map current when the plan started, never a crash or a route on stale cells.
#include <gtest/gtest.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>

#include <atomic>
#include <string>
#include <thread>

#include "eaci/io/occupancy_map.hpp"
#include "grid_conversion.hpp"
#include "node_log.hpp"
#include "map_pose.hpp"
#include "route_check.hpp"

namespace {

using eaci_test::mapPose;

const char* kService = "/eaci_planner_node/make_plan";

// A walled room of `width` x `height` cells at 0.1 m with its bottom-left corner at `origin`;
// `wall_col` >= 0 adds a wall across the room at that column with a one-cell door at
// `door_row` (rows from the top).
eaci::OccupancyMap room(int width, int height, Eigen::Vector2d origin, int wall_col = -1, int door_row = -1) {
  eaci::OccupancyMap map;
  map.width = width;
  map.height = height;
  map.resolution = 0.1;
  map.origin = origin;
  map.cells.assign(static_cast<std::size_t>(width) * height, eaci::kFreeValue);
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      const bool border = r == 0 || c == 0 || r == height - 1 || c == width - 1;
      const bool wall = c == wall_col && r != door_row;
      if (border || wall) map.cells[static_cast<std::size_t>(r) * width + c] = eaci::kOccupiedValue;
    }
  return map;
}

class MapChange : public ::testing::Test {
 protected:
  void SetUp() override {
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("/map", 1, true);
    ASSERT_TRUE(ros::service::waitForService(kService, ros::Duration(30.0)));
    // The node's log lines reach only a connected subscriber: ask for a start off every map
    // ("no map yet" before the first) until a line arrives.
    bool connected = false;
    for (int k = 0; k < 50 && !connected; ++k) {
      plan(mapPose(-100.0, -100.0), mapPose(0.35, 0.35));
      connected = !log_.waitFor({}, 0.2).empty();
    }
    ASSERT_TRUE(connected) << "no warning of eaci_planner_node on /rosout";
  }

  // The request gets an empty plan and the node names why: a warning or error of its own that
  // holds the outcome's word ("no plan (no_path)", PlanOutcome) and `part` of the sentence.
  void expectRefusedWith(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                         const std::string& outcome, const std::string& part) {
    log_.clear();
    EXPECT_TRUE(plan(start, goal).plan.poses.empty()) << "planned a request that must fail";
    const std::string word = "no plan (" + outcome + ")";
    EXPECT_NE(log_.waitFor({word, part}), "")
        << "no line of the node holds '" << word << "' and '" << part << "'; it said:" << log_.seen();
  }

  // Publishes `map` and waits until the node plans on it: a probe request from `probe_start`
  // to `probe_goal` (free on `map` only, or routed differently) must come back valid on it.
  void publish(const eaci::OccupancyMap& map) {
    map_pub_.publish(eaci_ros::toOccupancyGrid(map, "map"));
    ros::Duration(0.5).sleep();  // the node's map callback runs on its own spinner
  }

  nav_msgs::GetPlan::Response plan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal) {
    nav_msgs::GetPlan srv;
    srv.request.start = start;
    srv.request.goal = goal;
    EXPECT_TRUE(ros::service::call(kService, srv)) << "the service call itself failed";
    return srv.response;
  }

  static std::string defect(const eaci::OccupancyMap& map, const nav_msgs::Path& path, double sx, double sy,
                            double gx, double gy) {
    return eaci_test::routeDefect(map, path, *map.worldToCell({sx, sy}), *map.worldToCell({gx, gy}));
  }

  ros::NodeHandle nh_;
  ros::Publisher map_pub_;
  eaci_test::NodeLog log_{"/eaci_planner_node"};
};

}  // namespace

TEST_F(MapChange, RoutesFollowAMapThatGrowsMovesAndChangesBetweenRequests) {
  // 1. A 3 x 2 m room at the origin, open.
  const eaci::OccupancyMap small = room(30, 20, {0.0, 0.0});
  publish(small);
  auto response = plan(mapPose(0.35, 0.35), mapPose(2.55, 1.55));
  ASSERT_GE(response.plan.poses.size(), 2u);
  EXPECT_EQ(defect(small, response.plan, 0.35, 0.35, 2.55, 1.55), "");
  // A goal beyond this map is refused as off it.
  expectRefusedWith(mapPose(0.35, 0.35), mapPose(4.55, 1.55), "goal_off_map", "goal (4.55, 1.55)");

  // 2. The map grows to 6 x 4 m and its origin moves to (-1, -1) (the same world point is now
  //    another cell); a wall with a door at the top now stands at x = 1.55 m, across the straight
  //    line of the first route. The goal off the first map is now reachable.
  const eaci::OccupancyMap grown = room(60, 40, {-1.0, -1.0}, /*wall_col=*/25, /*door_row=*/5);
  publish(grown);
  response = plan(mapPose(0.35, 0.35), mapPose(2.55, 1.55));
  ASSERT_GE(response.plan.poses.size(), 2u);
  EXPECT_EQ(defect(grown, response.plan, 0.35, 0.35, 2.55, 1.55), "");
  // Through the door (row 5 from the top: y = -1 + (40 - 5 - 0.5) x 0.1 = 2.45 m).
  double highest = -1e9;
  for (const auto& p : response.plan.poses) highest = std::max(highest, p.pose.position.y);
  EXPECT_GT(highest, 2.35) << "the route did not go through the door of the new wall";
  response = plan(mapPose(0.35, 0.35), mapPose(4.55, 1.55));
  ASSERT_GE(response.plan.poses.size(), 2u);
  EXPECT_EQ(defect(grown, response.plan, 0.35, 0.35, 4.55, 1.55), "");

  // 2b. The same wall without its door: the far goal is on the map and free, but unreachable.
  publish(room(60, 40, {-1.0, -1.0}, /*wall_col=*/25));
  expectRefusedWith(mapPose(0.35, 0.35), mapPose(4.55, 1.55), "no_path", "cannot be reached");

  // 3. The map shrinks again (a rolling window moving away): the far goal is refused, the near
  //    one is planned on the small map's cells, and a start now off the map is refused.
  publish(small);
  expectRefusedWith(mapPose(0.35, 0.35), mapPose(4.55, 1.55), "goal_off_map", "goal (4.55, 1.55)");
  expectRefusedWith(mapPose(-0.55, -0.55), mapPose(1.55, 1.55), "start_off_map", "start (-0.55, -0.55)");
  response = plan(mapPose(0.35, 0.35), mapPose(2.55, 1.55));
  ASSERT_GE(response.plan.poses.size(), 2u);
  EXPECT_EQ(defect(small, response.plan, 0.35, 0.35, 2.55, 1.55), "");
}

TEST_F(MapChange, AMapArrivingDuringAPlanIsUsedByTheNextPlan) {
  // A larger room with a wall, planned with every iteration (see planner_map_change.test: many
  // iterations) while a different map arrives: the plan in progress finishes on the map it
  // started with (the node swaps maps between plans), the next one plans on the new map.
  const eaci::OccupancyMap before = room(120, 80, {0.0, 0.0}, /*wall_col=*/60, /*door_row=*/70);
  const eaci::OccupancyMap after = room(120, 80, {0.0, 0.0}, /*wall_col=*/60, /*door_row=*/10);
  publish(before);
  std::atomic<bool> planned{false};
  nav_msgs::GetPlan::Response during;
  std::thread request([&] {
    during = plan(mapPose(1.05, 4.05), mapPose(10.95, 4.05));
    planned = true;
  });
  ros::Duration(0.05).sleep();
  map_pub_.publish(eaci_ros::toOccupancyGrid(after, "map"));
  request.join();
  ASSERT_TRUE(planned);
  ASSERT_GE(during.plan.poses.size(), 2u);
  const std::string on_before = defect(before, during.plan, 1.05, 4.05, 10.95, 4.05);
  const std::string on_after = defect(after, during.plan, 1.05, 4.05, 10.95, 4.05);
  EXPECT_TRUE(on_before.empty() || on_after.empty())
      << "the route is valid on neither map: " << on_before << " / " << on_after;

  ros::Duration(0.5).sleep();
  const auto next = plan(mapPose(1.05, 4.05), mapPose(10.95, 4.05));
  ASSERT_GE(next.plan.poses.size(), 2u);
  EXPECT_EQ(defect(after, next.plan, 1.05, 4.05, 10.95, 4.05), "");
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_planner_map_change");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
