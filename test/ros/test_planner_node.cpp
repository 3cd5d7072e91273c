// Talks to a running eaci_planner_node (see planner_node.test) through its make_plan service.
#include <gtest/gtest.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>
#include <ros/ros.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>
#include <functional>
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

// What it planned, to see in RViz: ~grid_plan, the route before smoothing, and ~islands, EACI's
// islands, made only while someone listens. Both are latched: a plan asked before anyone
// subscribed leaves nothing for a late subscriber (nothing was made); with one, the grid route
// runs cell by cell (8-neighbour steps between free cells from the start's cell to the goal's)
// and the islands lie on free cells. (Start and goal inside their cells: 0.4 m lies on a cell
// border, which the node's float resolution puts in the cell below.)
TEST_F(PlannerNode, TheGridRouteAndTheIslandsArePublishedOnlyWhileSomeoneListens) {
  ASSERT_GE(plan(mapPose(0.42, 0.43), mapPose(4.38, 2.62)).plan.poses.size(), 2u);  // nobody listens yet
  ros::NodeHandle nh;
  std::mutex mutex;
  nav_msgs::Path grid_plan;
  visualization_msgs::MarkerArray islands;
  std::atomic<int> grid_plans{0}, island_arrays{0};
  const auto on_path = [&](const nav_msgs::Path::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex);
    grid_plan = *m;
    ++grid_plans;
  };
  const auto on_islands = [&](const visualization_msgs::MarkerArray::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex);
    islands = *m;
    ++island_arrays;
  };
  ros::Subscriber path_sub = nh.subscribe<nav_msgs::Path>("/eaci_planner_node/grid_plan", 1, on_path);
  ros::Subscriber islands_sub = nh.subscribe<visualization_msgs::MarkerArray>("/eaci_planner_node/islands", 1, on_islands);
  const auto wait_until = [](const std::function<bool()>& done, double seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!done() && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return done();
  };
  ASSERT_TRUE(wait_until([&] { return path_sub.getNumPublishers() > 0 && islands_sub.getNumPublishers() > 0; }, 10.0));
  std::this_thread::sleep_for(std::chrono::seconds(1));
  EXPECT_EQ(grid_plans.load(), 0) << "a grid route was made while nobody listened";
  EXPECT_EQ(island_arrays.load(), 0) << "islands were made while nobody listened";

  ASSERT_GE(plan(mapPose(0.42, 0.43), mapPose(4.38, 2.62)).plan.poses.size(), 2u);
  ASSERT_TRUE(wait_until([&] { return grid_plans.load() > 0 && island_arrays.load() > 0; }, 10.0));
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(grid_plan.header.frame_id, "map");
  ASSERT_GE(grid_plan.poses.size(), 2u);
  const auto cell_of = [&](const geometry_msgs::PoseStamped& p) {
    return map_.worldToCell({p.pose.position.x, p.pose.position.y});
  };
  EXPECT_EQ(*cell_of(grid_plan.poses.front()), *map_.worldToCell({0.42, 0.43}));
  EXPECT_EQ(*cell_of(grid_plan.poses.back()), *map_.worldToCell({4.38, 2.62}));
  for (std::size_t k = 0; k < grid_plan.poses.size(); ++k) {
    const auto& p = grid_plan.poses[k].pose.position;
    EXPECT_TRUE(freeAt(p.x, p.y)) << "grid pose " << k;
    if (k == 0) continue;
    const eaci::Cell a = *cell_of(grid_plan.poses[k - 1]), b = *cell_of(grid_plan.poses[k]);
    EXPECT_LE(std::max(std::abs(a.row - b.row), std::abs(a.col - b.col)), 1) << "grid pose " << k;
  }
  ASSERT_EQ(islands.markers.size(), 1u);
  const visualization_msgs::Marker& marker = islands.markers.front();
  EXPECT_EQ(marker.type, visualization_msgs::Marker::SPHERE_LIST);
  EXPECT_EQ(marker.header.frame_id, "map");
  EXPECT_GE(marker.points.size(), 2u);  // start and goal at least
  for (const auto& point : marker.points) EXPECT_TRUE(freeAt(point.x, point.y)) << point.x << ", " << point.y;
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
