// Talks to a running eaci_planner_node (see planner_node.test) through its make_plan service.
#include <gtest/gtest.h>
#include <nav_msgs/GetPlan.h>
#include <ros/ros.h>

#include <cmath>
#include <string>

#include "eaci/io/map_io.hpp"

namespace {

const char* kService = "/eaci_planner_node/make_plan";

geometry_msgs::PoseStamped pose(double x, double y, const std::string& frame = "map") {
  geometry_msgs::PoseStamped p;
  p.header.frame_id = frame;
  p.pose.position.x = x;
  p.pose.position.y = y;
  p.pose.orientation.w = 1.0;
  return p;
}

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
  }

  bool freeAt(double x, double y) const {
    const auto cell = map_.worldToCell({x, y});
    return cell && map_.cells[static_cast<std::size_t>(cell->row) * map_.width + cell->col] == eaci::kFreeValue;
  }

  eaci::OccupancyMap map_;
};

}  // namespace

TEST_F(PlannerNode, PlansACollisionFreeRouteAcrossTheLab) {
  const auto response = plan(pose(0.4, 0.4), pose(4.4, 2.6));
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

TEST_F(PlannerNode, BadRequestsGetAnEmptyPlanAndTheNodeStaysUp) {
  // Goal in the border wall (the map's bottom-left cell), no tolerance.
  EXPECT_FALSE(freeAt(0.025, 0.025));
  EXPECT_TRUE(plan(pose(0.4, 0.4), pose(0.025, 0.025)).plan.poses.empty());
  // Start in the wall.
  EXPECT_TRUE(plan(pose(0.025, 1.0), pose(4.4, 2.6)).plan.poses.empty());
  // Off the map.
  EXPECT_TRUE(plan(pose(0.4, 0.4), pose(10.0, 10.0)).plan.poses.empty());
  EXPECT_TRUE(plan(pose(-1.0, 0.4), pose(4.4, 2.6)).plan.poses.empty());
  // A frame nobody publishes.
  EXPECT_TRUE(plan(pose(0.4, 0.4, "nowhere"), pose(4.4, 2.6)).plan.poses.empty());
  EXPECT_TRUE(plan(pose(0.4, 0.4), pose(4.4, 2.6, "nowhere")).plan.poses.empty());
  // NaN.
  EXPECT_TRUE(plan(pose(std::nan(""), 0.4), pose(4.4, 2.6)).plan.poses.empty());
  // Still answering.
  EXPECT_FALSE(plan(pose(0.4, 0.4), pose(4.4, 2.6)).plan.poses.empty());
}

TEST_F(PlannerNode, GoalInAnObstacleMovesToTheNearestFreeCellWithinTolerance) {
  // (0.025, 1.5): a border-wall cell one cell from free space.
  EXPECT_FALSE(freeAt(0.025, 1.5));
  const auto response = plan(pose(0.4, 0.4), pose(0.025, 1.5), 0.2);
  ASSERT_FALSE(response.plan.poses.empty());
  const auto& last = response.plan.poses.back().pose.position;
  EXPECT_TRUE(freeAt(last.x, last.y));
  EXPECT_LE(std::hypot(last.x - 0.025, last.y - 1.5), 0.2 + 1e-6);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_planner_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
