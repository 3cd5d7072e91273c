// The goal tolerance by reachability (include/eaci/search/nearest_reachable.hpp): the cell
// nearest to the goal within the tolerance that the start can reach, as navfn chooses it.
#include <gtest/gtest.h>

#include <functional>
#include <optional>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/search/nearest_reachable.hpp"

namespace {

using eaci::Cell;

// 10 x 5, row 0 = top; 1 = obstacle. Columns 4 and 5 wall the right part off from the left.
eaci::CostGrid walledMap() {
  return eaci::CostGrid::fromRows({
                                      {0, 0, 0, 0, 1, 1, 0, 0, 0, 0},
                                      {0, 0, 0, 0, 1, 1, 0, 0, 0, 0},
                                      {0, 0, 0, 0, 1, 1, 0, 0, 0, 0},
                                      {0, 0, 0, 0, 1, 1, 0, 0, 0, 0},
                                      {0, 0, 0, 0, 1, 1, 0, 0, 0, 0},
                                  },
                                  false);
}

TEST(NearestReachable, AReachableGoalIsItself) {
  EXPECT_EQ(eaci::nearestReachableCell(walledMap(), Cell{2, 0}, Cell{0, 3}, 0.0), (Cell{0, 3}));
}

TEST(NearestReachable, AFreeCellBehindAWallLosesToAReachableOneFurtherAway) {
  // Goal (2, 5) in the wall: (2, 6) is free and 1 away but behind it; (2, 3) is 2 away and reachable.
  const eaci::CostGrid grid = walledMap();
  EXPECT_EQ(eaci::nearestReachableCell(grid, Cell{2, 0}, Cell{2, 5}, 2.0), (Cell{2, 3}));
  EXPECT_EQ(eaci::nearestReachableCell(grid, Cell{2, 0}, Cell{2, 5}, 1.9), std::nullopt);
  // From the right part, the same goal ends on the right: (2, 6).
  EXPECT_EQ(eaci::nearestReachableCell(grid, Cell{0, 9}, Cell{2, 5}, 2.0), (Cell{2, 6}));
}

TEST(NearestReachable, AFreeGoalTheStartCannotReachMovesToTheNearestReachableCell) {
  // Goal (1, 8): free but right of the wall. The reachable cells nearest to it are in column 3,
  // 5 away: (1, 3) exactly; (0, 3) and (2, 3) are sqrt(26) away.
  const eaci::CostGrid grid = walledMap();
  EXPECT_EQ(eaci::nearestReachableCell(grid, Cell{4, 0}, Cell{1, 8}, 5.0), (Cell{1, 3}));
  EXPECT_EQ(eaci::nearestReachableCell(grid, Cell{4, 0}, Cell{1, 8}, 4.99), std::nullopt);
}

TEST(NearestReachable, TiesGoToTheFirstInRowMajorOrder) {
  // Goal (2, 4) in the wall, and (2, 3) blocked too: no reachable cell 1 away; (1, 3) and (3, 3)
  // tie at sqrt 2 (the cells right of the wall at that distance are wall); (1, 3) comes first.
  eaci::CostGrid notched = walledMap();
  notched.setBlocked(Cell{2, 3}, true);
  EXPECT_EQ(eaci::nearestReachableCell(notched, Cell{0, 0}, Cell{2, 4}, 1.5), (Cell{1, 3}));
}

TEST(NearestReachable, AStopEndsItWithNone) {
  // 200 x 200 open cells: the flood asks the check after its first StopPoll::kWorkBetweenChecks cells.
  const eaci::CostGrid open(200, 200, false);
  EXPECT_EQ(eaci::nearestReachableCell(open, Cell{0, 0}, Cell{199, 199}, 10.0), (Cell{199, 199}));
  const std::function<bool()> stop_now = [] { return true; };
  EXPECT_EQ(eaci::nearestReachableCell(open, Cell{0, 0}, Cell{199, 199}, 10.0, stop_now), std::nullopt);
}

}  // namespace
