// Line-of-sight smoothing and pose orientation, against hand-computed routes and headings.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "eaci/path/orientation.hpp"
#include "eaci/path/smoothing.hpp"
#include "eaci/planner.hpp"
#include "eaci/search/astar.hpp"

using eaci::Cell;
using eaci::CellPath;
using eaci::CostGrid;

namespace {
CostGrid open(int rows, int cols) { return CostGrid::fromRows(std::vector<std::vector<int>>(rows, std::vector<int>(cols, 0)), false); }
}  // namespace

TEST(Smoothing, AStaircaseOnAnOpenGridBecomesOneSegment) {
  const CostGrid grid = open(5, 9);
  // (0,0) -> (4,8) as 4 diagonals then 4 straights: 4 sqrt2 + 4 = 9.657; the line is sqrt(80) = 8.944.
  const CellPath route{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}, {4, 5}, {4, 6}, {4, 7}, {4, 8}};
  const CellPath smoothed = eaci::smoothRoute(grid, route);
  ASSERT_EQ(smoothed, (CellPath{{0, 0}, {4, 8}}));
  EXPECT_NEAR(eaci::pathLength(smoothed), std::sqrt(80.0), 1e-12);
}

TEST(Smoothing, NeverCutsAcrossAnObstacleCorner) {
  // The segment (0,0) -> (2,2) passes exactly through the corners of cells (0,1)/(1,0) and
  // (1,2)/(2,1); with (1,2) blocked no shortcut past (1,1) is allowed.
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0}, {0, 0, 1}, {0, 0, 0}}, false);
  const CellPath route{{0, 0}, {1, 1}, {2, 1}, {2, 2}};
  const CellPath smoothed = eaci::smoothRoute(grid, route);
  for (std::size_t k = 1; k < smoothed.size(); ++k)
    EXPECT_TRUE(std::isfinite(eaci::segmentCost(grid, smoothed[k - 1], smoothed[k])));
  EXPECT_TRUE(std::isinf(eaci::segmentCost(grid, Cell{0, 0}, Cell{2, 2})));
  EXPECT_EQ(smoothed.front(), (Cell{0, 0}));
  EXPECT_EQ(smoothed.back(), (Cell{2, 2}));
}

TEST(Smoothing, TakesNoShortcutThatCostsMoreThanTheRoute) {
  // The centre cell costs 200: entering it costs 1 + 3 x 200 / 50 = 13 per cell of length. The
  // route around it costs 4; the diagonal (0,0) -> (2,2) would cost 0.707 + 1.414 x 13 + 0.707.
  CostGrid grid = open(3, 3);
  grid.setCost(Cell{1, 1}, 200);
  const CellPath route{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}};
  ASSERT_DOUBLE_EQ(eaci::routeCost(grid, route), 4.0);
  EXPECT_NEAR(eaci::segmentCost(grid, Cell{0, 0}, Cell{2, 2}), std::sqrt(2.0) * (0.5 + 13.0 + 0.5), 1e-9);
  const CellPath smoothed = eaci::smoothRoute(grid, route);
  EXPECT_GT(smoothed.size(), 2u);
  double cost = 0.0;
  for (std::size_t k = 1; k < smoothed.size(); ++k) cost += eaci::segmentCost(grid, smoothed[k - 1], smoothed[k]);
  EXPECT_LE(cost, 4.0 + 1e-9);
}

TEST(Smoothing, TakesNoShortcutNearerTheWallsThanTheRoute) {
  // 4 x 7 cells of cost 0 but (1,2), cost 30 (as next to a wall on a costmap). The route goes
  // down column 0 and along row 3: (0,0) ... (3,0), (3,1) ... (3,6), cost 9. The line
  // (0,0) -> (3,6) would be cheaper (6.708 plus a surcharge of 1.8 per cell of length inside
  // (1,2)) but enters (1,2); so does (0,0) -> (3,3), which touches it at a corner, and
  // (0,0) -> (3,4), which crosses it. (0,0) -> (3,2) passes (0,0), (1,0), (1,1), (2,1), (2,2),
  // (3,2) only. Hand-computed result: (0,0), (3,2), then straight along row 3 to (3,6).
  CostGrid grid = open(4, 7);
  grid.setCost(Cell{1, 2}, 30);
  const CellPath route{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}, {3, 4}, {3, 5}, {3, 6}};
  ASSERT_DOUBLE_EQ(eaci::routeCost(grid, route), 9.0);
  EXPECT_EQ(eaci::segmentCostAndPeak(grid, Cell{0, 0}, Cell{3, 6}).peak, 30);
  EXPECT_EQ(eaci::segmentCostAndPeak(grid, Cell{0, 0}, Cell{3, 3}).peak, 30);
  EXPECT_EQ(eaci::segmentCostAndPeak(grid, Cell{0, 0}, Cell{3, 2}).peak, 0);
  ASSERT_LT(eaci::segmentCost(grid, Cell{0, 0}, Cell{3, 6}), 9.0);  // cheaper, yet not taken
  EXPECT_EQ(eaci::smoothRoute(grid, route), (CellPath{{0, 0}, {3, 2}, {3, 6}}));
}

TEST(Smoothing, SegmentWalkEndsOnceOverABound) {
  // Row 0 of 10 cells of cost 0 but (0,5), cost 40. From (0,0) to (0,9) the segment lies half
  // a cell in each end cell and a whole cell in the 8 between: length 9, peak 40.
  CostGrid grid = open(1, 10);
  grid.setCost(Cell{0, 5}, 40);
  const double surcharge = 3.0 * 40 / 50;  // cost_factor x c / neutral_cost per unit length
  const auto whole = eaci::segmentCostAndPeak(grid, Cell{0, 0}, Cell{0, 9});
  EXPECT_NEAR(whole.cost, 9.0 + surcharge, 1e-12);
  EXPECT_EQ(whole.peak, 40);
  // Over a cost bound of 3 it stops after (0,3): 0.5 + 3 x 1 = 3.5, peak 0 so far.
  const auto over_cost = eaci::segmentCostAndPeak(grid, Cell{0, 0}, Cell{0, 9}, 3.0);
  EXPECT_NEAR(over_cost.cost, 3.5, 1e-12);
  EXPECT_EQ(over_cost.peak, 0);
  // Over a peak bound of 10 it stops in (0,5): 0.5 + 4 + (1 + surcharge).
  const auto over_peak = eaci::segmentCostAndPeak(grid, Cell{0, 0}, Cell{0, 9}, 100.0, 10);
  EXPECT_NEAR(over_peak.cost, 5.5 + surcharge, 1e-12);
  EXPECT_EQ(over_peak.peak, 40);
}

TEST(Smoothing, PlannerSmoothsOnlyWhenAsked) {
  const CostGrid grid = open(10, 10);
  eaci::Parameters p;
  const auto plain = eaci::plan(grid, Cell{0, 0}, Cell{9, 5}, eaci::Algorithm::kAStar, p);
  ASSERT_TRUE(plain.success());
  EXPECT_EQ(plain.smoothed_path, plain.path);
  p.smooth_path = true;
  const auto smooth = eaci::plan(grid, Cell{0, 0}, Cell{9, 5}, eaci::Algorithm::kAStar, p);
  EXPECT_EQ(smooth.path, plain.path);  // the search's route is unchanged
  EXPECT_EQ(smooth.smoothed_path, (CellPath{{0, 0}, {9, 5}}));
  EXPECT_NEAR(smooth.smoothed_length, std::sqrt(81.0 + 25.0), 1e-12);
}

TEST(Orientation, ModesSetHeadingsAsGlobalPlannerDoes) {
  // An L: east along y = 0, then north. Start heading 0.3, goal heading 2.0.
  const std::vector<Eigen::Vector2d> pts{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}};
  const double kEast = 0.0, kNorth = M_PI / 2;
  using eaci::OrientationMode;
  const auto forward = eaci::orientPoints(pts, 0.3, 2.0, OrientationMode::kForward);
  EXPECT_EQ(forward, (std::vector<double>{kEast, kEast, kNorth, kNorth, 2.0}));
  const auto none = eaci::orientPoints(pts, 0.3, 2.0, OrientationMode::kNone);
  EXPECT_EQ(none, (std::vector<double>{0.3, 0.0, 0.0, 0.0, 2.0}));
  const auto interpolate = eaci::orientPoints(pts, 0.3, 2.0, OrientationMode::kInterpolate);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(interpolate[static_cast<std::size_t>(k)], 0.3 + 1.7 * k / 4.0, 1e-12);
  // forward_then_interpolate: the last straight stretch starts at index 2 (north), so headings
  // 2..4 turn evenly from north to 2.0; before it, forward, with the start heading first.
  const auto ftoi = eaci::orientPoints(pts, 0.3, 2.0, OrientationMode::kForwardThenInterpolate);
  EXPECT_DOUBLE_EQ(ftoi[0], 0.3);
  EXPECT_DOUBLE_EQ(ftoi[1], kEast);
  EXPECT_DOUBLE_EQ(ftoi[2], kNorth);
  EXPECT_NEAR(ftoi[3], kNorth + (2.0 - kNorth) / 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(ftoi[4], 2.0);
  // backward / leftward / rightward: forward turned so that the -x / +y / -y axis points along
  // the route (global_planner: yaw + pi, yaw - pi/2, yaw + pi/2); the goal keeps its own heading.
  const auto backward = eaci::orientPoints(pts, 0.3, 2.0, OrientationMode::kBackward);
  const auto leftward = eaci::orientPoints(pts, 0.3, 2.0, OrientationMode::kLeftward);
  const auto rightward = eaci::orientPoints(pts, 0.3, 2.0, OrientationMode::kRightward);
  const std::vector<double> west_south{M_PI, M_PI, -M_PI / 2, -M_PI / 2};       // facing back along E, E, N, N
  const std::vector<double> south_east{-M_PI / 2, -M_PI / 2, 0.0, 0.0};         // +y along E, E, N, N
  const std::vector<double> north_west{M_PI / 2, M_PI / 2, M_PI, M_PI};         // -y along E, E, N, N
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(std::cos(backward[k]), std::cos(west_south[k]), 1e-12) << k;
    EXPECT_NEAR(std::sin(backward[k]), std::sin(west_south[k]), 1e-12) << k;
    EXPECT_NEAR(std::cos(leftward[k]), std::cos(south_east[k]), 1e-12) << k;
    EXPECT_NEAR(std::sin(leftward[k]), std::sin(south_east[k]), 1e-12) << k;
    EXPECT_NEAR(std::cos(rightward[k]), std::cos(north_west[k]), 1e-12) << k;
    EXPECT_NEAR(std::sin(rightward[k]), std::sin(north_west[k]), 1e-12) << k;
  }
  EXPECT_DOUBLE_EQ(backward[4], 2.0);
  EXPECT_DOUBLE_EQ(leftward[4], 2.0);
  EXPECT_DOUBLE_EQ(rightward[4], 2.0);
}

TEST(Orientation, ModeNamesAndNumbers) {
  EXPECT_EQ(eaci::orientationModeFromString("forward_then_interpolate"), eaci::OrientationMode::kForwardThenInterpolate);
  EXPECT_EQ(eaci::orientationModeFromString("2"), eaci::OrientationMode::kInterpolate);
  EXPECT_EQ(eaci::orientationModeFromString("4"), eaci::OrientationMode::kBackward);
  EXPECT_EQ(eaci::orientationModeFromString("leftward"), eaci::OrientationMode::kLeftward);
  EXPECT_EQ(eaci::orientationModeFromString("6"), eaci::OrientationMode::kRightward);
  EXPECT_THROW(eaci::orientationModeFromString("7"), std::invalid_argument);
  EXPECT_THROW(eaci::orientationModeFromString("sideways"), std::invalid_argument);
}

TEST(Smoothing, CellMidpointsAlongASegment) {
  // (0,0) -> (0,3): the stretches inside (0,1), (0,2), (0,3) have their middles at 1/3, 2/3, then the end.
  const auto ts = eaci::cellMidpointsAlong(Cell{0, 0}, Cell{0, 3});
  ASSERT_EQ(ts.size(), 3u);
  EXPECT_NEAR(ts[0], 1.0 / 3, 1e-12);
  EXPECT_NEAR(ts[1], 2.0 / 3, 1e-12);
  EXPECT_EQ(ts[2], 1.0);
  // (0,0) -> (2,2) runs through corners: only (1,1) and (2,2) are crossed.
  const auto diagonal = eaci::cellMidpointsAlong(Cell{0, 0}, Cell{2, 2});
  ASSERT_EQ(diagonal.size(), 2u);
  EXPECT_NEAR(diagonal[0], 0.5, 1e-12);
}
