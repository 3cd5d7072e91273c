// The simulated car's world (include/eaci/robot/sim_world.hpp): where a moving box stands, which
// cells a box covers, what the laser sees of boxes, and how near the car's footprint is to a wall
// or a box, against distances worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "eaci/robot/laser_scan.hpp"
#include "eaci/robot/sim_world.hpp"

using namespace eaci::robot;

namespace {

// 10 x 10 m in 0.1 m cells, origin (0, 0): cell (row, col) spans x from 0.1 col to 0.1 (col + 1)
// and y from 10 - 0.1 (row + 1) to 10 - 0.1 row.
eaci::MapFrame tenMetres() {
  eaci::MapFrame frame;
  frame.width = frame.height = 100;
  frame.resolution = 0.1;
  return frame;
}

std::vector<std::uint8_t> emptyCells() { return std::vector<std::uint8_t>(100 * 100, 0); }

Box box(double x, double y, double w, double h) { return {Eigen::Vector2d(x, y), Eigen::Vector2d(w, h)}; }

// The car of the paper, 265 x 205 mm.
const Eigen::Vector2d kCarHalf(0.1325, 0.1025);

Pose2 pose(double x, double y, double yaw) {
  Pose2 p;
  p.position = Eigen::Vector2d(x, y);
  p.orientation = Eigen::Rotation2Dd(yaw);
  return p;
}

}  // namespace

// From (0, 0) to (2, 0) at 1 m/s: out for 2 s, back for 2 s.
TEST(SimWorld, AMovingBoxGoesToTheEndOfItsLineAndBack) {
  MovingBox m{box(0, 0, 0.5, 0.5), Eigen::Vector2d(2, 0), 1.0};
  EXPECT_NEAR(boxAt(m, 0.0).centre.x(), 0.0, 1e-12);
  EXPECT_NEAR(boxAt(m, 0.5).centre.x(), 0.5, 1e-12);
  EXPECT_NEAR(boxAt(m, 2.0).centre.x(), 2.0, 1e-12);
  EXPECT_NEAR(boxAt(m, 3.0).centre.x(), 1.0, 1e-12);
  EXPECT_NEAR(boxAt(m, 4.0).centre.x(), 0.0, 1e-12);
  EXPECT_NEAR(boxAt(m, 5.5).centre.x(), 1.5, 1e-12);
  EXPECT_DOUBLE_EQ(boxAt(m, 5.5).centre.y(), 0.0);
  EXPECT_DOUBLE_EQ(boxAt(m, 5.5).size.x(), 0.5);
}

// A 0.2 m box on cell borders covers 2 x 2 cells; one of 0.25 m overlaps 4 x 4 and covers them
// all (a cell that only touches the box's edge is not covered).
TEST(SimWorld, ABoxCoversEveryCellItSharesInteriorWith) {
  const eaci::MapFrame frame = tenMetres();
  const auto count = [&](const Box& b) {
    int n = 0;
    for (int row = 0; row < 100; ++row)
      for (int col = 0; col < 100; ++col) n += covers(b, frame, {row, col});
    return n;
  };
  EXPECT_EQ(count(box(0.5, 0.5, 0.2, 0.2)), 4);
  EXPECT_TRUE(covers(box(0.5, 0.5, 0.2, 0.2), frame, {95, 4}));   // x 0.4-0.5, y 0.4-0.5
  EXPECT_FALSE(covers(box(0.5, 0.5, 0.2, 0.2), frame, {95, 3}));  // x 0.3-0.4: touches the edge only
  EXPECT_EQ(count(box(0.5, 0.5, 0.25, 0.25)), 16);
}

// The sensor at (2.05, 5.05) looking along +x; a fixed box from x = 4.8 to 5.2 across the beam.
TEST(SimWorld, TheLaserSeesAFixedBoxAtItsNearFace) {
  SimWorld world(tenMetres(), emptyCells(), {box(5.0, 5.0, 0.4, 1.0)});
  LaserSpec spec;
  spec.beams = 1;
  spec.angle_min = 0.0;
  const auto ranges = castScan(world.frame(), world.at(0.0), Eigen::Vector2d(2.05, 5.05), 0.0, spec);
  EXPECT_NEAR(ranges[0], 2.75, 1e-5);
}

// A box crossing the beam's line at 1 m/s: in the beam at time 0, out of it (1.5 m up) at 1.5 s.
TEST(SimWorld, TheLaserSeesTheMovingBoxOnlyWhereItIs) {
  MovingBox m{box(5.0, 5.0, 0.4, 0.4), Eigen::Vector2d(5.0, 8.0), 1.0};
  SimWorld world(tenMetres(), emptyCells(), {}, m);
  LaserSpec spec;
  spec.beams = 1;
  spec.angle_min = 0.0;
  spec.range_max = 8.0;
  EXPECT_NEAR(castScan(world.frame(), world.at(0.0), Eigen::Vector2d(2.05, 5.05), 0.0, spec)[0], 2.75, 1e-5);
  EXPECT_EQ(castScan(world.frame(), world.at(1.5), Eigen::Vector2d(2.05, 5.05), 0.0, spec)[0],
            std::numeric_limits<float>::infinity());
  EXPECT_NEAR(castScan(world.frame(), world.at(6.0), Eigen::Vector2d(2.05, 5.05), 0.0, spec)[0], 2.75, 1e-5);
}

// A wall of column 30 (x from 3.0 to 3.1): the car at (2, 2) facing it keeps 3.0 - 2.1325 m;
// turned a quarter, its side (0.1025 m from the centre) faces the wall.
TEST(SimWorld, TheFootprintsClearanceFromAWallIsTheGapToItsNearFace) {
  std::vector<std::uint8_t> cells = emptyCells();
  for (int row = 0; row < 100; ++row) cells[row * 100 + 30] = 1;
  SimWorld world(tenMetres(), cells);
  EXPECT_NEAR(world.footprintClearance(pose(2, 2, 0), kCarHalf, 0, 1.0), 0.8675, 1e-9);
  EXPECT_NEAR(world.footprintClearance(pose(2, 2, kPi / 2), kCarHalf, 0, 1.0), 0.8975, 1e-9);
  EXPECT_DOUBLE_EQ(world.footprintClearance(pose(2, 2, 0), kCarHalf, 0, 0.5), 0.5);  // nothing within reach
  EXPECT_DOUBLE_EQ(world.footprintClearance(pose(2.9, 2, 0), kCarHalf, 0, 1.0), 0.0);  // it overlaps the wall
}

// Boxes as they are, not as cells: a box above the car, one off its corner, one moving onto it.
TEST(SimWorld, TheFootprintsClearanceFromABoxIsMeasuredToTheBoxItself) {
  SimWorld above(tenMetres(), emptyCells(), {box(2.0, 2.5, 0.2, 0.2)});
  EXPECT_NEAR(above.footprintClearance(pose(2, 2, 0), kCarHalf, 0, 1.0), 2.4 - 2.1025, 1e-9);
  SimWorld corner(tenMetres(), emptyCells(), {box(2.5, 2.5, 0.2, 0.2)});
  EXPECT_NEAR(corner.footprintClearance(pose(2, 2, 0), kCarHalf, 0, 1.0), std::hypot(2.4 - 2.1325, 2.4 - 2.1025), 1e-9);
  SimWorld moving(tenMetres(), emptyCells(), {}, MovingBox{box(2.0, 4.0, 0.2, 0.2), Eigen::Vector2d(2.0, 2.0), 1.0});
  EXPECT_NEAR(moving.footprintClearance(pose(2, 2, 0), kCarHalf, 0.0, 3.0), 3.9 - 2.1025, 1e-9);
  EXPECT_DOUBLE_EQ(moving.footprintClearance(pose(2, 2, 0), kCarHalf, 2.0, 3.0), 0.0);
}

// A box of 0.2 m walking from x = 0 to x = 4 at 1 m/s towards a car standing across its line at
// x = 2 (its near side at x = 2 - 0.1325): the box stops 0.1 m short of it, waits 2 s, turns round.
TEST(SimWorld, TheMovingBoxWaitsShortOfTheCarThenTurnsRound) {
  const MovingBox m{box(0, 0, 0.2, 0.2), Eigen::Vector2d(4, 0), 1.0};
  const auto car = corners(pose(2, 0, 0), kCarHalf);
  const auto distance = [&](const Box& b) { return quadDistance(car, corners(b)); };
  BoxWalker walker;
  double nearest = 10.0, furthest_x = 0.0;
  for (int tick = 0; tick < 250; ++tick) {  // 2.5 s at 0.01 s
    walker.step(m, 0.01, 0.1, 2.0, distance);
    nearest = std::min(nearest, distance(boxAt(m, walker.clock)));
    furthest_x = std::max(furthest_x, boxAt(m, walker.clock).centre.x());
  }
  EXPECT_GT(nearest, 0.1);
  EXPECT_NEAR(furthest_x, 2.0 - 0.1325 - 0.1 - 0.1, 0.011);  // its front edge 0.1 m from the car
  EXPECT_DOUBLE_EQ(walker.direction, 1.0);                    // 1.67 s walking, 0.83 s waiting
  for (int tick = 0; tick < 200; ++tick) walker.step(m, 0.01, 0.1, 2.0, distance);  // turns at 3.67 s
  EXPECT_DOUBLE_EQ(walker.direction, -1.0);
  EXPECT_LT(boxAt(m, walker.clock).centre.x(), furthest_x - 0.5);  // walking back the way it came
}

// A car beside the line, nearer than the margin, does not hold a box walking away from it.
TEST(SimWorld, TheMovingBoxWalksAwayFromACarBesideIt) {
  const MovingBox m{box(1.0, 0, 0.2, 0.2), Eigen::Vector2d(4, 0), 1.0};
  const auto car = corners(pose(1.0, 0.2, 0), kCarHalf);  // overlapping the box, even
  BoxWalker walker;
  walker.step(m, 0.1, 0.1, 2.0, [&](const Box& b) { return quadDistance(car, corners(b)); });
  EXPECT_NEAR(boxAt(m, walker.clock).centre.x(), 1.1, 1e-9);
}

TEST(SimWorld, RefusesABoxWithoutSizeAndAMapOfTheWrongSize) {
  EXPECT_THROW(SimWorld(tenMetres(), emptyCells(), {box(1, 1, 0.0, 0.5)}), std::invalid_argument);
  EXPECT_THROW(SimWorld(tenMetres(), emptyCells(), {}, MovingBox{box(1, 1, 0.5, 0.5), Eigen::Vector2d(2, 2), -1.0}),
               std::invalid_argument);
  EXPECT_THROW(SimWorld(tenMetres(), std::vector<std::uint8_t>(10, 0)), std::invalid_argument);
  try {
    SimWorld(tenMetres(), emptyCells(), {box(1, 1, -0.2, 0.5)});
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("size"), std::string::npos) << e.what();
  }
}
