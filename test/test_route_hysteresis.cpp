// Keeping the route sent last (eaci/path/route_hysteresis.hpp): a smoothed route's cost by the
// planners' objective and the previous route rejoined from the robot's cell, against hand
// computations.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "eaci/path/route_hysteresis.hpp"

using eaci::Cell;
using eaci::CellPath;
using eaci::CostGrid;

namespace {
CostGrid open(int rows, int cols) { return CostGrid::fromRows(std::vector<std::vector<int>>(rows, std::vector<int>(cols, 0)), false); }
}  // namespace

TEST(RouteHysteresis, PolylineObjectiveIsCostPlusTurning) {
  CostGrid grid = open(5, 5);
  // (0,0) -> (0,4) -> (4,4): 4 + 4 cells of length (half a cell in each end cell), one 90-degree
  // turn: 8 + turn_cost x pi / 2.
  const CellPath corner{{0, 0}, {0, 4}, {4, 4}};
  EXPECT_NEAR(eaci::polylineObjective(grid, corner, 0.0), 8.0, 1e-12);
  EXPECT_NEAR(eaci::polylineObjective(grid, corner, 2.0), 8.0 + M_PI, 1e-12);
  // A cell of cost 10 on the way: (50 + 3 x 10) / 50 = 1.6 per unit length, one cell: + 0.6.
  grid.setCost(Cell{0, 2}, 10);
  EXPECT_NEAR(eaci::polylineObjective(grid, corner, 2.0), 8.6 + M_PI, 1e-12);
  // A repeated corner adds neither length nor a turn; a straight corner adds no turn.
  EXPECT_NEAR(eaci::polylineObjective(grid, CellPath{{0, 0}, {0, 4}, {0, 4}, {4, 4}}, 2.0), 8.6 + M_PI, 1e-12);
  EXPECT_NEAR(eaci::polylineObjective(grid, CellPath{{4, 0}, {4, 2}, {4, 4}}, 2.0), 4.0, 1e-12);
  // Turning back on itself is a turn of pi.
  EXPECT_NEAR(eaci::polylineObjective(grid, CellPath{{4, 0}, {4, 4}, {4, 1}}, 1.0), 4.0 + 3.0 + M_PI, 1e-12);
  grid.setBlocked(Cell{2, 4}, true);
  EXPECT_EQ(eaci::polylineObjective(grid, corner, 0.0), std::numeric_limits<double>::infinity());
}

TEST(RouteHysteresis, PolylineObjectivePricesTheTurnsAtItsEnds) {
  const CostGrid grid = open(5, 5);
  const CellPath corner{{0, 0}, {0, 4}, {4, 4}};  // east along row 0, then south (row + 1)
  eaci::EndHeadings ends;
  ends.start = M_PI / 2;  // facing north: the first leg (east) turns 90 degrees
  EXPECT_NEAR(eaci::polylineObjective(grid, corner, 2.0, ends), 8.0 + 2.0 * (M_PI / 2 + M_PI / 2), 1e-12);
  ends.goal = 0.0;  // facing east at the goal: the last leg (south) turns 90 more
  EXPECT_NEAR(eaci::polylineObjective(grid, corner, 2.0, ends), 8.0 + 2.0 * 3 * M_PI / 2, 1e-12);
  ends.start = std::numeric_limits<double>::quiet_NaN();
  ends.goal = -M_PI / 2 + 4 * M_PI;  // south, any turn count: lined up
  EXPECT_NEAR(eaci::polylineObjective(grid, corner, 2.0, ends), 8.0 + M_PI, 1e-12);
  // A route that does not move turns nothing, whatever the headings.
  ends.start = 0.0;
  ends.goal = M_PI;
  EXPECT_EQ(eaci::polylineObjective(grid, CellPath{{2, 2}, {2, 2}}, 2.0, ends), 0.0);
}

TEST(RouteHysteresis, RejoinRouteFromTheNearestPoint) {
  const CellPath previous{{0, 0}, {0, 10}, {10, 10}};
  // One cell beside the first segment, at column 4: on to (0,10) and the rest.
  EXPECT_EQ(eaci::rejoinRoute(previous, Cell{1, 4}, 2.0), (CellPath{{1, 4}, {0, 10}, {10, 10}}));
  // Beside the second segment, at row 3: straight on to the goal.
  EXPECT_EQ(eaci::rejoinRoute(previous, Cell{3, 11}, 2.0), (CellPath{{3, 11}, {10, 10}}));
  // On the route's start: the whole route. On its corner: from there on.
  EXPECT_EQ(eaci::rejoinRoute(previous, Cell{0, 0}, 2.0), previous);
  EXPECT_EQ(eaci::rejoinRoute(previous, Cell{0, 10}, 2.0), (CellPath{{0, 10}, {10, 10}}));
  // (5,5) is 5 cells from both segments: farther than 2, the robot has left the route.
  EXPECT_TRUE(eaci::rejoinRoute(previous, Cell{5, 5}, 2.0).empty());
  EXPECT_EQ(eaci::rejoinRoute(previous, Cell{5, 5}, 5.0).front(), (Cell{5, 5}));
  // At the goal, or without a segment: nothing to keep.
  EXPECT_TRUE(eaci::rejoinRoute(previous, Cell{10, 10}, 2.0).empty());
  EXPECT_TRUE(eaci::rejoinRoute(CellPath{{3, 3}}, Cell{3, 3}, 2.0).empty());
  EXPECT_TRUE(eaci::rejoinRoute(CellPath{}, Cell{3, 3}, 2.0).empty());
}
