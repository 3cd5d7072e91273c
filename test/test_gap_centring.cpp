// Lines bent through the middle of gaps (path/gap_centring.hpp), against hand-placed walls and
// doors whose middles and clearances are worked out here.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "eaci/metrics/path_metrics.hpp"
#include "eaci/path/gap_centring.hpp"

using eaci::Cell;
using eaci::CellPath;
using eaci::CellPoint;
using eaci::CellPolyline;
using eaci::CostGrid;

namespace {

// 21 x 21 free cells with a wall down column 10 and a door in it: rows `first` .. `last` free.
CostGrid wallWithDoor(int first, int last) {
  CostGrid grid = CostGrid::fromRows(std::vector<std::vector<int>>(21, std::vector<int>(21, 0)), false);
  for (int r = 0; r < 21; ++r)
    if (r < first || r > last) grid.setBlocked(Cell{r, 10}, true);
  return grid;
}

double clearance(const CostGrid& grid, const CellPolyline& line) {
  return eaci::minPolylineClearance(grid, line, eaci::obstacleTransform(grid));
}

}  // namespace

TEST(GapCentring, ALineHalfACellOffAnEvenDoorsMiddleBendsThroughIt) {
  // A door of 4 cells (rows 8..11): its middle is row 9.5, 2.5 from the wall ends at rows 7 and
  // 12. The route along row 9 passes the end at row 7 at 2.
  const CostGrid grid = wallWithDoor(8, 11);
  const CellPath route{{9, 0}, {9, 20}};
  EXPECT_DOUBLE_EQ(clearance(grid, eaci::cellPolyline(route)), 2.0);
  const CellPolyline driven = eaci::centreInGaps(grid, route, 1.0);
  ASSERT_EQ(driven.size(), 3u);
  EXPECT_EQ(driven.front(), CellPoint(0, 9));
  EXPECT_EQ(driven.back(), CellPoint(20, 9));
  EXPECT_NEAR(driven[1].y(), 9.5, 0.1);  // the middle, across the line
  EXPECT_NEAR(driven[1].x(), 10.0, 0.5);
  // Lines from row 9 at the ends to 9.5 at the door: within a few hundredths of the middle's 2.5.
  EXPECT_GT(clearance(grid, driven), 2.4);
}

TEST(GapCentring, ALineThroughAnOddDoorsMiddleStaysStraight) {
  // 5 cells (rows 8..12): row 10 is the middle, 3 from both ends.
  const CostGrid grid = wallWithDoor(8, 12);
  const CellPolyline driven = eaci::centreInGaps(grid, {{10, 0}, {10, 20}}, 1.0);
  EXPECT_EQ(driven, (CellPolyline{{0, 10}, {20, 10}}));
}

TEST(GapCentring, ALinePassingOneWallEndMovesAwayByNoMoreThanTheShift) {
  // The wall ends at row 8 (a door from row 9 down to the map's edge, no wall on the far side):
  // the line along row 10 passes the end at 2; bent by 1 cell it would pass at 3.
  const CostGrid grid = wallWithDoor(9, 20);
  const CellPolyline driven = eaci::centreInGaps(grid, {{10, 0}, {10, 20}}, 1.0);
  ASSERT_EQ(driven.size(), 3u);
  EXPECT_GT(driven[1].y(), 10.5);
  EXPECT_LE(driven[1].y(), 11.0 + 1e-9);
  EXPECT_GT(clearance(grid, driven), 2.5);
  EXPECT_LE(clearance(grid, driven), 3.0 + 1e-9);
}

TEST(GapCentring, NeverEntersACellCostlierThanTheLinesCostliest) {
  // The door of ALineHalfACellOff..., with row 10 (towards the middle) costing 100 in the door's
  // column and the cells round it, and row 9 (the line's) 50 there: the bend may move within row
  // 9's cells (up to row 9.5, exclusive) and not into row 10's.
  CostGrid grid = wallWithDoor(8, 11);
  for (int c = 5; c <= 15; ++c) {
    if (c == 10) continue;
    grid.setCost(Cell{9, c}, 50);
    grid.setCost(Cell{10, c}, 100);
  }
  grid.setCost(Cell{9, 10}, 50);
  grid.setCost(Cell{10, 10}, 100);
  const CellPolyline driven = eaci::centreInGaps(grid, {{9, 0}, {9, 20}}, 1.0);
  for (std::size_t k = 1; k < driven.size(); ++k)
    for (int i = 0; i <= 100; ++i) {
      const Cell c = eaci::cellOfPoint(driven[k - 1] + (driven[k] - driven[k - 1]) * (i / 100.0));
      EXPECT_LE(grid.cost(c), 50) << "row " << c.row << " col " << c.col;
    }
  EXPECT_GE(clearance(grid, driven), 2.0);  // never nearer the walls than the line
}

TEST(GapCentring, CornersStayEvenInADoor) {
  // The door of rows 8..11 with a corner of the route in it, on row 9, half a cell off the
  // middle: corners are not moved (only lines bend), nor are start and goal.
  const CostGrid grid = wallWithDoor(8, 11);
  const CellPolyline driven = eaci::centreInGaps(grid, {{9, 0}, {9, 10}, {9, 20}}, 1.0);
  ASSERT_GE(driven.size(), 3u);
  EXPECT_EQ(driven.front(), CellPoint(0, 9));
  EXPECT_NE(std::find(driven.begin(), driven.end(), CellPoint(10, 9)), driven.end());
  EXPECT_EQ(driven.back(), CellPoint(20, 9));
}

TEST(GapCentring, OffEmptyOrStoppedTheCornersStayAsTheyAre) {
  const CostGrid grid = wallWithDoor(8, 11);
  const CellPath route{{9, 0}, {9, 20}};
  EXPECT_EQ(eaci::centreInGaps(grid, route, 0.0), eaci::cellPolyline(route));
  EXPECT_TRUE(eaci::centreInGaps(grid, {}, 1.0).empty());
  const auto stop_now = [] { return true; };
  eaci::StopPoll poll(stop_now, 0, 1);
  poll.askNow();
  EXPECT_EQ(eaci::centreInGaps(grid, route, 1.0, &poll), eaci::cellPolyline(route));
}

TEST(GapCentring, ALineWithoutObstaclesNearItStaysStraight) {
  const CostGrid grid = CostGrid::fromRows(std::vector<std::vector<int>>(40, std::vector<int>(40, 0)), false);
  EXPECT_EQ(eaci::centreInGaps(grid, {{0, 0}, {39, 39}}, 1.0), (CellPolyline{{0, 0}, {39, 39}}));
}
