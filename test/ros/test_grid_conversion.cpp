// The ROS <-> core conversions, without a rosmaster.
#include <gtest/gtest.h>
#include <ros/time.h>
#include <tf2/utils.h>

#include <cmath>

#include "eaci/grid/nearest_free.hpp"
#include "grid_conversion.hpp"

using eaci::Cell;

namespace {

// 4 columns x 3 rows at 0.5 m, origin (-1, 2). Buffer rows bottom first: the top-right cell is
// buffer row 2, column 3.
nav_msgs::OccupancyGrid sampleGrid() {
  nav_msgs::OccupancyGrid g;
  g.header.frame_id = "map";
  g.info.resolution = 0.5f;
  g.info.width = 4;
  g.info.height = 3;
  g.info.origin.position.x = -1.0;
  g.info.origin.position.y = 2.0;
  g.info.origin.orientation.w = 1.0;
  g.data = {0, 0, 0, 0,      // bottom row
            0, 100, -1, 0,   // middle: occupied, unknown
            0, 0, 0, 70};    // top row: 70 is occupied at threshold 65
  return g;
}

}  // namespace

TEST(GridConversion, WorldToCellUsesTheBottomLeftOriginAndTopFirstRows) {
  const auto frame = eaci_ros::frameOf(sampleGrid());
  EXPECT_EQ(frame.worldToCell({-0.9, 2.1}), (Cell{2, 0}));  // bottom-left cell
  EXPECT_EQ(frame.worldToCell({0.9, 3.4}), (Cell{0, 3}));   // top-right cell
  EXPECT_FALSE(frame.worldToCell({-1.01, 2.1}));
  EXPECT_FALSE(frame.worldToCell({1.0, 2.1}));  // x = origin + width: off the map
  EXPECT_FALSE(frame.worldToCell({std::nan(""), 2.1}));
  const Eigen::Vector2d centre = frame.cellToWorld(Cell{0, 3});
  EXPECT_DOUBLE_EQ(centre.x(), 0.75);
  EXPECT_DOUBLE_EQ(centre.y(), 3.25);
}

TEST(GridConversion, ViewReadsOccupancyWithoutCopying) {
  const auto grid = sampleGrid();
  const auto view = eaci_ros::viewOf(grid, 65, false);
  EXPECT_TRUE(view.isObstacle(Cell{1, 1}));   // 100
  EXPECT_TRUE(view.isObstacle(Cell{1, 2}));   // unknown as obstacle
  EXPECT_TRUE(view.isObstacle(Cell{0, 3}));   // 70 >= 65
  EXPECT_FALSE(view.isObstacle(Cell{2, 0}));
  EXPECT_FALSE(eaci_ros::viewOf(grid, 65, true).isObstacle(Cell{1, 2}));  // unknown allowed: passable,
  EXPECT_EQ(eaci_ros::viewOf(grid, 65, true).cost(Cell{1, 2}), 252);     // at costmap_2d's dearest passable cost
  EXPECT_FALSE(eaci_ros::viewOf(grid, 75, false).isObstacle(Cell{0, 3}));
  nav_msgs::OccupancyGrid malformed = grid;
  malformed.data.pop_back();
  EXPECT_TRUE(eaci_ros::viewOf(malformed, 65, false).empty());
}

TEST(GridConversion, NearestFreeCellWithinTolerance) {
  const auto grid = sampleGrid();
  const auto view = eaci_ros::viewOf(grid, 65, false);
  EXPECT_EQ(eaci::nearestFreeCell(view, Cell{2, 2}, 0.0), (Cell{2, 2}));  // already free
  EXPECT_FALSE(eaci::nearestFreeCell(view, Cell{1, 1}, 0.5));            // neighbours are 1 cell away
  const auto moved = eaci::nearestFreeCell(view, Cell{1, 1}, 1.0);
  ASSERT_TRUE(moved);
  EXPECT_EQ(std::abs(moved->row - 1) + std::abs(moved->col - 1), 1);
  EXPECT_TRUE(view.isFree(*moved));
}

// The poses are the service's points as they are (PlanReply::poses, checked there), each facing
// the next one, the last with the goal's orientation.
TEST(GridConversion, PathPosesAreThePointsFacingTheNextAndEndWithTheGoalPose) {
  ros::Time::init();
  geometry_msgs::PoseStamped start, goal;
  start.pose.position.x = -0.8;
  start.pose.position.y = 2.2;
  goal.pose.position.x = 0.7;
  goal.pose.position.y = 3.3;
  goal.pose.orientation.z = std::sin(0.25);
  goal.pose.orientation.w = std::cos(0.25);  // yaw 0.5
  const std::vector<Eigen::Vector2d> points{{-0.8, 2.2}, {-0.25, 2.25}, {0.25, 2.75}, {0.7, 3.3}};
  const auto path = eaci_ros::toPath(points, "map", start, goal, ros::Time(1.0));
  ASSERT_EQ(path.poses.size(), 4u);
  EXPECT_EQ(path.header.frame_id, "map");
  EXPECT_EQ(path.poses[2].header.frame_id, "map");
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_EQ(path.poses[k].pose.position.x, points[k].x()) << k;
    EXPECT_EQ(path.poses[k].pose.position.y, points[k].y()) << k;
  }
  // (-0.25, 2.25) -> (0.25, 2.75): up and right, 45 degrees.
  EXPECT_NEAR(tf2::getYaw(path.poses[1].pose.orientation), M_PI / 4, 1e-9);
  EXPECT_NEAR(tf2::getYaw(path.poses[3].pose.orientation), 0.5, 1e-9);
  EXPECT_TRUE(eaci_ros::toPath({}, "map", start, goal, ros::Time(1.0)).poses.empty());
}

// The islands as one sphere list at their cells' centres, two cells wide; none: a deletion.
TEST(GridConversion, IslandsAreOneSphereListAtTheirCentres) {
  const auto frame = eaci_ros::frameOf(sampleGrid());
  const auto markers = eaci_ros::islandMarkers({{2, 0}, {1, 2}}, frame, ros::Time(2.0));
  ASSERT_EQ(markers.markers.size(), 1u);
  const auto& m = markers.markers[0];
  EXPECT_EQ(m.type, visualization_msgs::Marker::SPHERE_LIST);
  EXPECT_EQ(m.header.frame_id, "map");
  ASSERT_EQ(m.points.size(), 2u);
  EXPECT_DOUBLE_EQ(m.points[0].x, frame.cellToWorld({2, 0}).x());
  EXPECT_DOUBLE_EQ(m.points[1].y, frame.cellToWorld({1, 2}).y());
  EXPECT_DOUBLE_EQ(m.scale.x, 2.0 * frame.resolution);
  EXPECT_EQ(eaci_ros::islandMarkers({}, frame, ros::Time(2.0)).markers[0].action, visualization_msgs::Marker::DELETE);
}

TEST(GridConversion, InflationGrowsObstaclesByTheRadius) {
  auto grid = sampleGrid();
  eaci_ros::inflateObstacles(grid, 0.5, 65);  // one cell
  const auto view = eaci_ros::viewOf(grid, 65, false);
  EXPECT_TRUE(view.isObstacle(Cell{1, 0}));   // left of the 100
  EXPECT_TRUE(view.isObstacle(Cell{2, 1}));   // below it
  EXPECT_FALSE(view.isObstacle(Cell{2, 0}));  // diagonal: sqrt2 cells away
  EXPECT_TRUE(view.isObstacle(Cell{1, 3}));   // below the 70
}

TEST(GridConversion, FieldToGridIsLogScaledAndBottomRowFirst) {
  const auto frame = eaci_ros::frameOf(sampleGrid());
  std::vector<double> field(12, 0.0);
  field[0] = 1.0;    // top-left (row 0)
  field[11] = 100.0; // bottom-right (row 2)
  field[5] = 10.0;   // row 1, col 1
  const auto grid = eaci_ros::fieldToGrid(field, frame, ros::Time(1.0));
  ASSERT_EQ(grid.data.size(), 12u);
  EXPECT_EQ(grid.data[8], 0);     // top-left: the smallest positive value
  EXPECT_EQ(grid.data[3], 100);   // bottom-right: the largest
  EXPECT_EQ(grid.data[5], 50);    // log-midway
}
