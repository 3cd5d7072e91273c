// Route length, total corner angle, clearance and mean cell cost.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "eaci/metrics/path_metrics.hpp"

using eaci::Cell;
using eaci::CellPath;
using eaci::CostGrid;

TEST(PathMetrics, LengthCountsStraightAsOneAndDiagonalAsRootTwo) {
  EXPECT_DOUBLE_EQ(eaci::pathLength({}), 0.0);
  EXPECT_DOUBLE_EQ(eaci::pathLength({Cell{3, 3}}), 0.0);
  EXPECT_NEAR(eaci::pathLength({{0, 0}, {0, 1}, {1, 2}, {2, 2}}), 2.0 + std::sqrt(2.0), 1e-12);
  // 30.97 = 14 + 12 sqrt2, the paper's 20x20 figure.
  CellPath p{{0, 0}};
  for (int k = 0; k < 12; ++k) p.push_back(Cell{p.back().row + 1, p.back().col + 1});
  for (int k = 0; k < 14; ++k) p.push_back(Cell{p.back().row, p.back().col + 1});
  EXPECT_NEAR(eaci::pathLength(p), 30.9706, 1e-4);
}

TEST(PathMetrics, TotalTurnAngleSumsTheTurnsInDegrees) {
  EXPECT_DOUBLE_EQ(eaci::totalTurnDegrees({{0, 0}, {0, 1}, {0, 2}}), 0.0);
  EXPECT_DOUBLE_EQ(eaci::totalTurnDegrees({{0, 0}, {0, 1}, {1, 2}, {2, 2}}), 90.0);   // 45 + 45
  EXPECT_DOUBLE_EQ(eaci::totalTurnDegrees({{0, 0}, {0, 1}, {1, 1}, {1, 0}}), 180.0);  // 90 + 90
  EXPECT_DOUBLE_EQ(eaci::totalTurnDegrees({{1, 0}, {1, 1}, {0, 0}}), 135.0);
}

TEST(PathMetrics, MinClearanceAlongARowTwoCellsFromAWall) {
  // Row 0 is a wall; the route runs along row 2.
  const CostGrid grid = CostGrid::fromRows({{1, 1, 1, 1, 1},
                                            {0, 0, 0, 0, 0},
                                            {0, 0, 0, 0, 0},
                                            {0, 0, 0, 0, 0},
                                            {0, 0, 0, 0, 0}},
                                           false);
  EXPECT_DOUBLE_EQ(eaci::minClearance(grid, {{2, 0}, {2, 1}, {2, 2}, {2, 3}, {2, 4}}), 2.0);
  EXPECT_DOUBLE_EQ(eaci::minClearance(grid, {{4, 0}, {3, 1}, {4, 2}}), 3.0);  // the nearest cell decides
  EXPECT_DOUBLE_EQ(eaci::minClearance(grid, {{1, 2}}), 1.0);
}

TEST(PathMetrics, MinClearanceOfADiagonalNeighbourIsRootTwo) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0, 0},
                                            {0, 1, 0, 0},
                                            {0, 0, 0, 0},
                                            {0, 0, 0, 0}},
                                           false);
  EXPECT_DOUBLE_EQ(eaci::minClearance(grid, {{2, 2}, {3, 3}}), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(eaci::minClearance(grid, {{3, 3}, {3, 2}}), std::sqrt(5.0));  // (2, 1) away
  EXPECT_DOUBLE_EQ(eaci::minClearance(grid, {{3, 3}}), std::sqrt(8.0));
  EXPECT_DOUBLE_EQ(eaci::minClearance(grid, {{1, 1}}), 0.0);  // a blocked cell
}

TEST(PathMetrics, PolylineClearanceIsMeasuredAlongTheLinesNotOnlyAtCellCentres) {
  // One obstacle at (2, 2) in 5 x 6 cells. The line (0,0) -> (3,5) (x = col, y = row) passes it
  // at |2 x 5 - 2 x 3| / sqrt(34) = 4 / sqrt 34 = 0.686 cells; the cells it runs through are
  // at least 1 from it (minClearance of its two corners: (0,0) 2.83, (3,5) 3.16).
  std::vector<std::vector<int>> rows(5, std::vector<int>(6, 0));
  rows[2][2] = 1;
  const CostGrid grid = CostGrid::fromRows(rows, false);
  EXPECT_NEAR(eaci::minPolylineClearance(grid, {{0, 0}, {3, 5}}), 4.0 / std::sqrt(34.0), 1e-12);
  // Two segments, the nearer point at a corner: (0,0) -> (0,4) -> (4,4): the corner (0,4) is
  // sqrt 8 away, the first segment passes (0,2) at 2, the second (2,4) at 2.
  EXPECT_DOUBLE_EQ(eaci::minPolylineClearance(grid, {{0, 0}, {0, 4}, {4, 4}}), 2.0);
  // A long line, many pieces: (4,0) -> (4,5) passes (4,2) at 2.
  EXPECT_DOUBLE_EQ(eaci::minPolylineClearance(grid, {{4, 0}, {4, 5}}), 2.0);
  // One corner alone: minClearance's.
  EXPECT_DOUBLE_EQ(eaci::minPolylineClearance(grid, {{0, 0}}), std::sqrt(8.0));
  // No obstacle: infinite.
  const CostGrid open = CostGrid::fromRows({{0, 0, 0}, {0, 0, 0}}, false);
  EXPECT_EQ(eaci::minPolylineClearance(open, {{0, 0}, {1, 2}}), std::numeric_limits<double>::infinity());
}

TEST(PathMetrics, PolylineClearanceTakesCornersOffTheCellCentres) {
  // One obstacle at (row 2, col 2). The line x = 4.5 (between columns 4 and 5), rows 0..4,
  // passes it at 2.5; the corner (x 0.5, y 2.5) alone is sqrt(1.5^2 + 0.5^2) from it.
  std::vector<std::vector<int>> rows(5, std::vector<int>(6, 0));
  rows[2][2] = 1;
  const CostGrid grid = CostGrid::fromRows(rows, false);
  EXPECT_DOUBLE_EQ(eaci::minPolylineClearance(grid, eaci::CellPolyline{{4.5, 0.0}, {4.5, 4.0}}, eaci::obstacleTransform(grid)), 2.5);
  EXPECT_DOUBLE_EQ(eaci::minPolylineClearance(grid, eaci::CellPolyline{{0.5, 2.5}}, eaci::obstacleTransform(grid)),
                   std::sqrt(2.5));
}

TEST(PathMetrics, MinClearanceFindsTheEuclideanNearestBeyondTheFirstRing) {
  // On ring 3 at (3, 3) diagonal lies sqrt 18 = 4.24; ring 4 holds (4, 0) at exactly 4.
  std::vector<std::vector<int>> rows(9, std::vector<int>(9, 0));
  rows[0][0] = 1;  // from (3, 3): (-3, -3), 4.24
  rows[3][7] = 1;  // (0, +4): 4
  const CostGrid grid = CostGrid::fromRows(rows, false);
  EXPECT_DOUBLE_EQ(eaci::minClearance(grid, {{3, 3}}), 4.0);
}

TEST(PathMetrics, MinClearanceIgnoresTheMapBorderAndIsInfiniteWithoutObstacles) {
  const CostGrid open = CostGrid::fromRows({{0, 0, 0}, {0, 0, 0}}, false);
  EXPECT_EQ(eaci::minClearance(open, {{0, 0}, {0, 1}}), std::numeric_limits<double>::infinity());
  const CostGrid one = CostGrid::fromRows({{0, 0, 0}, {0, 0, 1}}, false);
  EXPECT_DOUBLE_EQ(eaci::minClearance(one, {{0, 0}}), std::sqrt(5.0));  // the border, 1 away, does not count
  EXPECT_EQ(eaci::minClearance(one, {}), std::numeric_limits<double>::infinity());
}

TEST(PathMetrics, MinClearanceEqualsABruteForceSearchOnRandomGrids) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int w = 1 + static_cast<int>(random() % 17), h = 1 + static_cast<int>(random() % 17);
    const unsigned density = random() % 40;  // percent; some grids get no obstacle at all
    CostGrid grid(w, h, false);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) grid.setBlocked(Cell{r, c}, random() % 100 < density);
    CellPath route;
    for (int n = static_cast<int>(random() % 6); n >= 0; --n)
      route.push_back(Cell{static_cast<int>(random() % h), static_cast<int>(random() % w)});
    double expected = std::numeric_limits<double>::infinity();
    for (const Cell& a : route)
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
          if (grid.isBlocked(Cell{r, c})) expected = std::min(expected, std::hypot(r - a.row, c - a.col));
    EXPECT_DOUBLE_EQ(eaci::minClearance(grid, route), expected) << "trial " << trial;
  }
}

TEST(PathMetrics, MeanCellCostOfAHandBuiltCostGrid) {
  CostGrid grid(4, 1, false);
  grid.setCost(Cell{0, 0}, 0);
  grid.setCost(Cell{0, 1}, 10);
  grid.setCost(Cell{0, 2}, 50);
  grid.setCost(Cell{0, 3}, 254);
  EXPECT_DOUBLE_EQ(eaci::meanCellCost(grid, {{0, 0}, {0, 1}, {0, 2}}), 20.0);  // (0 + 10 + 50) / 3
  EXPECT_DOUBLE_EQ(eaci::meanCellCost(grid, {{0, 2}, {0, 3}}), 152.0);        // (50 + 254) / 2
  EXPECT_DOUBLE_EQ(eaci::meanCellCost(grid, {{0, 0}}), 0.0);
  EXPECT_TRUE(std::isnan(eaci::meanCellCost(grid, {})));
  grid.setBlocked(Cell{0, 1}, true);
  EXPECT_TRUE(std::isnan(eaci::meanCellCost(grid, {{0, 0}, {0, 1}})));  // not a route
}

TEST(LineClearance, IsLookedForWithinTheReachOnly) {
  // One obstacle at (3,5) in an open 10 x 10 grid; the segment (0,0) -> (0,8) passes 3 from it
  // (at (0,5)), the segment (0,0) -> (6,0) 5 (at (3,0)); the cell (0,0) sqrt(9 + 25). Points are
  // (column, row).
  CostGrid grid = CostGrid::fromRows(std::vector<std::vector<int>>(10, std::vector<int>(10, 0)), false);
  grid.setBlocked(Cell{3, 5}, true);
  EXPECT_DOUBLE_EQ(eaci::segmentClearanceWithin(grid, {0.0, 0.0}, {8.0, 0.0}, 10.0), 3.0);
  EXPECT_DOUBLE_EQ(eaci::segmentClearanceWithin(grid, {0.0, 0.0}, {8.0, 0.0}, 2.5), 2.5);  // beyond the reach
  EXPECT_DOUBLE_EQ(eaci::segmentClearanceWithin(grid, {0.0, 0.0}, {0.0, 6.0}, 10.0), 5.0);
  // The polyline's: its nearest segment's, and a corner's own (a polyline of one cell).
  EXPECT_DOUBLE_EQ(eaci::polylineClearanceWithin(grid, {{6, 0}, {0, 0}, {0, 8}}, 10.0), 3.0);
  EXPECT_DOUBLE_EQ(eaci::polylineClearanceWithin(grid, {{0, 0}}, 10.0), std::sqrt(34.0));
  EXPECT_DOUBLE_EQ(eaci::polylineClearanceWithin(grid, {{0, 0}}, 4.0), 4.0);
  // minPolylineClearance, looking as far as the distance transform says, agrees.
  EXPECT_DOUBLE_EQ(eaci::minPolylineClearance(grid, CellPath{{6, 0}, {0, 0}, {0, 8}}), 3.0);
}
