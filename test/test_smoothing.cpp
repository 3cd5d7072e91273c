// Line-of-sight smoothing and pose orientation, against hand-computed routes and headings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
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

// An L corridor 11 cells wide in a 40 x 40 grid (a wall fills rows 11..39 x columns 0..28),
// with a cost band along the walls and the map's edge as on a costmap: a free cell 1, 2, 3, 4
// cells (Chebyshev) from a wall or outside costs 200, 150, 100, 50, farther 0. The corridor's
// middle (row 5, column 34) is 6 cells from every wall: cost 0.
CostGrid lCorridorWithBand() {
  CostGrid grid = open(40, 40);
  const auto wall = [](int r, int c) { return r < 0 || c < 0 || r >= 40 || c >= 40 || (r >= 11 && c <= 28); };
  for (int r = 0; r < 40; ++r)
    for (int c = 0; c < 40; ++c) {
      if (wall(r, c)) {
        grid.setBlocked(Cell{r, c}, true);
        continue;
      }
      int near = 99;
      for (int dr = -4; dr <= 4; ++dr)
        for (int dc = -4; dc <= 4; ++dc)
          if (wall(r + dr, c + dc)) near = std::min(near, std::max(std::abs(dr), std::abs(dc)));
      if (near <= 4) grid.setCost(Cell{r, c}, static_cast<std::uint8_t>(250 - 50 * near));
    }
  return grid;
}
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

TEST(Smoothing, ATolerancePassesNearerTheCorner) {
  // A 3 x 3 band of cost 20 (every cell costs 1 + 3 x 20 / 50 = 2.2 per cell of length) whose
  // inner corner (1,1) costs 24 (2.44 per cell), as nearer a wall. The route around the corner,
  // (0,0) (0,1) (0,2) (1,2) (2,2), costs 4 x 2.2 = 8.8 and peaks at 20. The diagonal
  // (0,0) -> (2,2) costs 0.707 x 2.2 + 1.414 x 2.44 + 0.707 x 2.2 = 6.561 and peaks at 24:
  // cheaper, but nearer the wall. Without a tolerance the smoother keeps the corner, (0,0) (0,2)
  // (2,2): (0,0) -> (1,2) crosses (1,1). With 0.2 a shortcut may enter cells up to
  // floor(20 x 1.2) = 24: the corner is cut in one segment. With 0.1 (up to 22) it is not.
  CostGrid grid = open(3, 3);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) grid.setCost(Cell{r, c}, 20);
  grid.setCost(Cell{1, 1}, 24);
  const CellPath route{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}};
  ASSERT_NEAR(eaci::routeCost(grid, route), 8.8, 1e-9);
  const eaci::SegmentCost diagonal = eaci::segmentCostAndPeak(grid, Cell{0, 0}, Cell{2, 2});
  EXPECT_NEAR(diagonal.cost, std::sqrt(2.0) * (0.5 * 2.2 + 2.44 + 0.5 * 2.2), 1e-9);
  EXPECT_EQ(diagonal.peak, 24);
  EXPECT_EQ(eaci::smoothRoute(grid, route), (CellPath{{0, 0}, {0, 2}, {2, 2}}));
  EXPECT_EQ(eaci::smoothRoute(grid, route, nullptr, 0.1), (CellPath{{0, 0}, {0, 2}, {2, 2}}));
  EXPECT_EQ(eaci::smoothRoute(grid, route, nullptr, 0.2), (CellPath{{0, 0}, {2, 2}}));
  // Never through an obstacle, whatever the tolerance: a wall at the inner corner keeps it.
  grid.setBlocked(Cell{1, 1}, true);
  EXPECT_EQ(eaci::smoothRoute(grid, route, nullptr, 1.0), (CellPath{{0, 0}, {0, 2}, {2, 2}}));
}

TEST(Smoothing, AShortcutAnswersForItsTurnAtTheRoutesEnds) {
  // Free cells (a segment costs its length). The route runs north from (8,4) to (4,4), then
  // north-west to the goal (0,0): 4 + 4 sqrt 2 = 9.657. The straight shortcut (8,4) -> (0,0),
  // sqrt 80 = 8.944, heads 116.6 degrees (atan2(8, -4)), 18.4 off a goal heading of 135 (the
  // last leg's, which turns nothing onto it) and 26.6 off a start heading of 90 (the first
  // leg's). With turn_cost 1 it still pays: 8.944 + 0.322 < 9.657 (and + 0.464 at the start).
  // With turn_cost 3 it does not (8.944 + 0.965 > 9.657): the goal keeps its last leg, from
  // the earliest cell whose shortcut into the goal is allowed. (4,4) -> (0,0) lies on the
  // leg; (5,4) -> (0,0) heads 128.7 degrees: 6.403 + 3 x 0.110 > 1 + 4 sqrt 2 = 6.657.
  const CostGrid grid = open(9, 6);
  const CellPath route{{8, 4}, {7, 4}, {6, 4}, {5, 4}, {4, 4}, {3, 3}, {2, 2}, {1, 1}, {0, 0}};
  const CellPath straight{{8, 4}, {0, 0}}, two_legs{{8, 4}, {4, 4}, {0, 0}};
  EXPECT_EQ(eaci::smoothRoute(grid, route), straight);
  eaci::EndHeadings goal_heading;
  goal_heading.goal = 3 * M_PI / 4;
  EXPECT_EQ(eaci::smoothRoute(grid, route, nullptr, 0.0, 1.0, goal_heading), straight);
  EXPECT_EQ(eaci::smoothRoute(grid, route, nullptr, 0.0, 3.0, goal_heading), two_legs);
  EXPECT_EQ(eaci::smoothRoute(grid, route, nullptr, 0.0, 0.0, goal_heading), straight);  // not priced
  // The start heading of 90 degrees, alone: (8,4) -> (3,3) heads 101.3 degrees, 11.3 off it,
  // and 5.099 + 3 x 0.197 > 4 + sqrt 2 = 5.414: the first leg stays.
  eaci::EndHeadings start_heading;
  start_heading.start = M_PI / 2;
  EXPECT_EQ(eaci::smoothRoute(grid, route, nullptr, 0.0, 1.0, start_heading), straight);
  EXPECT_EQ(eaci::smoothRoute(grid, route, nullptr, 0.0, 3.0, start_heading), two_legs);
  // And the planner smooths with them: A* (turn_cost 3, the heading search) from (8,4) to
  // (0,0) heading north-west at the goal ends on a north-west leg.
  eaci::Parameters params;
  params.turn_cost = 3.0;
  eaci::PlanOptions options;
  options.end_headings = goal_heading;
  const eaci::PlanResult r = eaci::plan(grid, Cell{8, 4}, Cell{0, 0}, eaci::Algorithm::kAStar, params, options);
  ASSERT_TRUE(r.success()) << r.error;
  ASSERT_GE(r.smoothed_path.size(), 2u);
  const Cell before = r.smoothed_path[r.smoothed_path.size() - 2];
  EXPECT_EQ(before.row, before.col) << "the last segment runs along the north-west diagonal";
}

TEST(Smoothing, PlannerPassesTheTolerance) {
  // A 3 x 3 band of cost 20 but (1,0), cost 24. The only shortest route from (0,0) to (2,2) is
  // the diagonal (0,0) (1,1) (2,2), peak 20; the straight segment (0,0) -> (2,2) touches (1,0)
  // at the corner it passes, peak 24: without a tolerance the smoother keeps (1,1), with
  // smooth_tolerance 0.2 (up to 24) the route is one segment.
  CostGrid grid = open(3, 3);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) grid.setCost(Cell{r, c}, 20);
  grid.setCost(Cell{1, 0}, 24);
  eaci::Parameters p;
  p.smooth_path = true;
  const eaci::PlanResult strict = eaci::plan(grid, Cell{0, 0}, Cell{2, 2}, eaci::Algorithm::kAStar, p);
  ASSERT_EQ(strict.path, (CellPath{{0, 0}, {1, 1}, {2, 2}}));
  EXPECT_EQ(strict.smoothed_path, strict.path);
  p.smooth_tolerance = 0.2;
  const eaci::PlanResult loose = eaci::plan(grid, Cell{0, 0}, Cell{2, 2}, eaci::Algorithm::kAStar, p);
  ASSERT_EQ(loose.path, strict.path);
  EXPECT_EQ(loose.smoothed_path, (CellPath{{0, 0}, {2, 2}}));
}

TEST(Smoothing, RoundCornersCutsARightAngle) {
  // An open 11 x 11 grid (cost 0: cost = length), the corner (0,10) between (0,0) and (10,10).
  // d_max = min(10, 10 / 2) = 5: a = (0,5), b = (5,10); p a b n is 5 + 5 sqrt(2) + 5 long,
  // shorter than 20, and free: the 90-degree corner becomes two of 45.
  const CostGrid grid = open(11, 11);
  const CellPath corner{{0, 0}, {0, 10}, {10, 10}};
  EXPECT_EQ(eaci::roundCorners(grid, corner, 0), corner);
  EXPECT_EQ(eaci::roundCorners(grid, corner, 1), (CellPath{{0, 0}, {0, 5}, {5, 10}, {10, 10}}));
  // Keeping the last leg (a goal heading priced), the bend before the goal stays; a bend before
  // it is still cut.
  EXPECT_EQ(eaci::roundCorners(grid, corner, 2, 0.0, nullptr, true), corner);
  EXPECT_EQ(eaci::roundCorners(grid, CellPath{{10, 0}, {0, 0}, {0, 10}, {10, 10}}, 1, 0.0, nullptr, true),
            (CellPath{{10, 0}, {5, 0}, {0, 5}, {0, 10}, {10, 10}}));
  // A second pass cuts both 45-degree corners again: no turn of the result reaches 45 degrees
  // (each is about 22.5, give or take the rounding to cells), and every segment stays on the map.
  const CellPath twice = eaci::roundCorners(grid, corner, 2);
  ASSERT_GT(twice.size(), 4u);
  EXPECT_EQ(twice.front(), corner.front());
  EXPECT_EQ(twice.back(), corner.back());
  for (std::size_t k = 1; k + 1 < twice.size(); ++k) {
    const double h1 = std::atan2(twice[k].row - twice[k - 1].row, twice[k].col - twice[k - 1].col);
    const double h2 = std::atan2(twice[k + 1].row - twice[k].row, twice[k + 1].col - twice[k].col);
    EXPECT_LT(std::abs(std::remainder(h2 - h1, 2 * M_PI)), M_PI / 4) << "corner " << k;
    EXPECT_TRUE(std::isfinite(eaci::segmentCost(grid, twice[k - 1], twice[k])));
  }
}

TEST(Smoothing, RoundCornersKeepsOffTheInnerWall) {
  // A 9 x 9 grid whose rows 3..8 x columns 0..5 are a wall: an L corridor three cells wide
  // (rows 0..2, columns 6..8). The route down its middle turns at (1,7) between (1,0) and (8,7).
  // d_max = min(7, 7 / 2) = 3.5: a = (1, 3.5 -> 4), b = (4.5 -> 5, 7); the segment (1,4) -> (5,7)
  // crosses row 3 at column 5.5, in the wall. d = 1.75: a = (1, 5.25 -> 5), b = (2.75 -> 3, 7);
  // (1,5) -> (3,7) passes (1,5), (2,6), (3,7) and touches (1,6), (2,5), (2,7), (3,6), all free.
  CostGrid grid = open(9, 9);
  for (int r = 3; r < 9; ++r)
    for (int c = 0; c < 6; ++c) grid.setBlocked(Cell{r, c}, true);
  const CellPath corner{{1, 0}, {1, 7}, {8, 7}};
  EXPECT_FALSE(std::isfinite(eaci::segmentCost(grid, Cell{1, 4}, Cell{5, 7})));
  EXPECT_EQ(eaci::roundCorners(grid, corner, 1), (CellPath{{1, 0}, {1, 5}, {3, 7}, {8, 7}}));
}

TEST(Smoothing, RoundCornersPassesNoNearerTheWallsThanTheBend) {
  // The L corridor of lCorridorWithBand, a route down its middle from (5,1), in the band (cost
  // 150, two cells from the map's edge), round the corner (5,34) to (33,34) (cost 0). The
  // corner's cells are all 6 cells from the walls, cost 0. With a tolerance of 2 x, the cost
  // allows every cut below and the cut's cells must cost at most 2 x 0: d_max = min(33, 28 / 2) = 14. d = 14: (5,20) -> (19,34)
  // crosses the wall at (13,28). d = 7: (5,27) -> (12,34) passes (7,29), 4 cells from the inner
  // corner (11,28), cost 50. d = 3.5: (5, 30.5 -> 31) -> (8.5 -> 9, 34) passes (7,32), cost 50.
  // d = 1.75: (5, 32.25 -> 32) -> (6.75 -> 7, 34) passes (6,33) and touches (5,33), (6,32),
  // (6,34), (7,33), all 5 or more cells from every wall: cost 0, taken. Although the route began
  // in the band (a rule against the costliest cell of the whole stretch would let the cut in).
  const CostGrid grid = lCorridorWithBand();
  ASSERT_EQ(grid.cost(Cell{5, 1}), 150);
  ASSERT_EQ(grid.cost(Cell{7, 29}), 50);
  ASSERT_EQ(grid.cost(Cell{7, 32}), 50);
  ASSERT_EQ(grid.cost(Cell{6, 32}), 0);
  const CellPath corner{{5, 1}, {5, 34}, {33, 34}};
  EXPECT_EQ(eaci::roundCorners(grid, corner, 1, 1.0), (CellPath{{5, 1}, {5, 32}, {7, 34}, {33, 34}}));
  // A second pass finds no cut of the bend (5,32)..(7,34) that keeps to cost 0 (each enters the
  // band nearer the inner corner), and leaves the route as it was.
  EXPECT_EQ(eaci::roundCorners(grid, corner, 2, 1.0), (CellPath{{5, 1}, {5, 32}, {7, 34}, {33, 34}}));
}

TEST(Smoothing, RoundCornersPassesNoNearerAnObstacleThanTheCornerItCutsOff) {
  // A 21 x 21 grid, every cell cost 100 (all in an obstacle's band), one post at (2,4) beside
  // the first leg of the corner (0,10) between (0,0) and (10,10), as a door post beside a route
  // that turns after the door. Every cut is shorter and as dear a cell, so the cost rule allows
  // each; the clearance decides. d = 5: the corner cut off, (0,5) (0,10) (5,10), keeps
  // sqrt 5 = 2.24 from the post (at (0,5)); the cut (0,5) -> (5,10) turns towards it and passes
  // 3 / sqrt 2 = 2.12 from it: not taken (the route itself passes 2 from it, at (0,4): a rule
  // against the whole route's clearance would take it). d = 2.5: the corner (0,8) (0,10) (3,10)
  // and the cut (0,8) -> (3,10) both keep sqrt 20 = 4.47 (at (0,8)): taken.
  CostGrid grid = open(21, 21);
  for (int r = 0; r < 21; ++r)
    for (int c = 0; c < 21; ++c) grid.setCost(Cell{r, c}, 100);
  grid.setBlocked(Cell{2, 4}, true);
  const CellPath corner{{0, 0}, {0, 10}, {10, 10}};
  EXPECT_EQ(eaci::roundCorners(grid, corner, 1, 0.1), (CellPath{{0, 0}, {0, 8}, {3, 10}, {10, 10}}));
  // Without the post the first cut is taken, as on the open grid.
  grid.setBlocked(Cell{2, 4}, false);
  grid.setCost(Cell{2, 4}, 100);
  EXPECT_EQ(eaci::roundCorners(grid, corner, 1, 0.1), (CellPath{{0, 0}, {0, 5}, {5, 10}, {10, 10}}));
}

TEST(Smoothing, PlannerRoundsCornersWhenAsked) {
  // The L corridor of lCorridorWithBand, from (5,0) to (39,31) in the band at the map's bottom
  // edge. The route turns round the inner corner in two 45-degree corners one diagonal cell
  // apart, down the corridor's middle, and bends again before the goal. With a tolerance of
  // 10 % the planner's smoothed route with round_corners is its route without, rounded
  // (roundCorners, tested above by hand: the bend round the inner corner stays, every cut of
  // it passing nearer the corner; the one before the goal is cut), and it passes only free cells.
  const CostGrid grid = lCorridorWithBand();
  eaci::Parameters p;
  p.smooth_path = true;
  p.smooth_tolerance = 0.1;
  const eaci::PlanResult plain = eaci::plan(grid, Cell{5, 0}, Cell{39, 31}, eaci::Algorithm::kAStar, p);
  p.round_corners = 1;
  const eaci::PlanResult rounded = eaci::plan(grid, Cell{5, 0}, Cell{39, 31}, eaci::Algorithm::kAStar, p);
  ASSERT_TRUE(plain.success());
  ASSERT_TRUE(rounded.success());
  EXPECT_EQ(rounded.path, plain.path);  // the search's route is unchanged
  EXPECT_NE(rounded.smoothed_path, plain.smoothed_path);
  EXPECT_EQ(rounded.smoothed_path, eaci::roundCorners(grid, plain.smoothed_path, 1, 0.1));
  for (std::size_t k = 1; k < rounded.smoothed_path.size(); ++k)
    EXPECT_TRUE(std::isfinite(eaci::segmentCost(grid, rounded.smoothed_path[k - 1], rounded.smoothed_path[k])));
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

TEST(Orientation, TheTravelHeadingIsTheAxisTheModeDrivesAlong) {
  // forward (and the modes that blend it): the robot's x axis; backward: -x; leftward: +y;
  // rightward: -y. NaN (no heading) stays NaN.
  const double yaw = 0.3;
  EXPECT_DOUBLE_EQ(eaci::travelHeading(yaw, eaci::OrientationMode::kForward), 0.3);
  EXPECT_DOUBLE_EQ(eaci::travelHeading(yaw, eaci::OrientationMode::kNone), 0.3);
  EXPECT_DOUBLE_EQ(eaci::travelHeading(yaw, eaci::OrientationMode::kInterpolate), 0.3);
  EXPECT_DOUBLE_EQ(eaci::travelHeading(yaw, eaci::OrientationMode::kBackward), 0.3 + M_PI);
  EXPECT_DOUBLE_EQ(eaci::travelHeading(yaw, eaci::OrientationMode::kLeftward), 0.3 + M_PI / 2);
  EXPECT_DOUBLE_EQ(eaci::travelHeading(yaw, eaci::OrientationMode::kRightward), 0.3 - M_PI / 2);
  EXPECT_TRUE(std::isnan(eaci::travelHeading(std::nan(""), eaci::OrientationMode::kBackward)));
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

// The one segment walk (grid/segment_walk.hpp), by hand: each cell with the length inside it,
// corners' side cells and the cells beyond an end on a border with 0.
std::vector<std::pair<Cell, double>> walked(const eaci::CellPoint& from, const eaci::CellPoint& to) {
  std::vector<std::pair<Cell, double>> cells;
  eaci::walkSegment(from, to, [&](Cell c, double length) {
    cells.emplace_back(c, length);
    return true;
  });
  return cells;
}

TEST(SegmentWalk, EveryCellWithItsLength) {
  const auto along = walked({0, 0}, {3, 0});  // (row 0, col 0) to (row 0, col 3)
  ASSERT_EQ(along.size(), 4u);
  const double along_lengths[] = {0.5, 1, 1, 0.5};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(along[k].first, (Cell{0, k}));
    EXPECT_NEAR(along[k].second, along_lengths[k], 1e-12) << k;
  }
  // The diagonal through two corners: the side cells of each with 0.
  const auto diagonal = walked({0, 0}, {2, 2});
  const std::vector<Cell> cells{{0, 0}, {0, 1}, {1, 0}, {1, 1}, {1, 2}, {2, 1}, {2, 2}};
  const double lengths[] = {M_SQRT1_2, 0, 0, M_SQRT2, 0, 0, M_SQRT1_2};
  ASSERT_EQ(diagonal.size(), cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    EXPECT_EQ(diagonal[k].first, cells[k]) << k;
    EXPECT_NEAR(diagonal[k].second, lengths[k], 1e-12) << k;
  }
  // Off the centres: an end on a border touches the cell beyond; a start on a border lies in the cell ahead.
  const auto to_border = walked({0.2, 0}, {0.5, 0});
  ASSERT_EQ(to_border.size(), 2u);
  EXPECT_NEAR(to_border[0].second, 0.3, 1e-12);
  EXPECT_EQ(to_border[1], (std::pair<Cell, double>{Cell{0, 1}, 0.0}));
  const auto from_border = walked({0.5, 0}, {0.0, 0});
  ASSERT_EQ(from_border.size(), 1u);
  EXPECT_EQ(from_border[0].first, (Cell{0, 0}));
  EXPECT_NEAR(from_border[0].second, 0.5, 1e-12);
  // One point: its cell, length 0.
  ASSERT_EQ(walked({1, 1}, {1, 1}).size(), 1u);
}
