// Eq. 12: the auxiliary map, on hand-made cases.
#include <gtest/gtest.h>

#include "eaci/aco/auxiliary_map.hpp"

using eaci::CostGrid;
using eaci::Cell;

namespace {
// r0: 0 0 0 0
// r1: 0 1 0 0
// r2: 1 0 0 0
// r3: 0 0 0 0
CostGrid sample() {
  return CostGrid::fromRows({{0, 0, 0, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 0}}, false);
}
}  // namespace

TEST(AuxiliaryMap, BlocksCellsWithTwoPerpendicularObstacleNeighbours) {
  const CostGrid aux = eaci::auxiliaryMap(sample(), Cell{3, 3}, Cell{0, 3});
  EXPECT_TRUE(aux.isBlocked(Cell{1, 0}));   // right (1,1) and down (2,0)
  EXPECT_TRUE(aux.isBlocked(Cell{2, 1}));   // left (2,0) and up (1,1)
  EXPECT_FALSE(aux.isBlocked(Cell{0, 1}));  // only down is an obstacle
  EXPECT_FALSE(aux.isBlocked(Cell{1, 2}));  // only left
  EXPECT_FALSE(aux.isBlocked(Cell{3, 0}));  // only up
  EXPECT_TRUE(aux.isBlocked(Cell{1, 1}));   // obstacles stay obstacles
  int blocked = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) blocked += aux.isBlocked(Cell{r, c});
  EXPECT_EQ(blocked, 4);
}

TEST(AuxiliaryMap, OppositeObstaclesDoNotBlock) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0}, {1, 0, 1}, {0, 0, 0}}, false);
  const CostGrid aux = eaci::auxiliaryMap(grid, Cell{0, 0}, Cell{2, 2});
  EXPECT_FALSE(aux.isBlocked(Cell{1, 1}));  // left and right: a corridor, not a trap
}

TEST(AuxiliaryMap, ReadsTheOriginalMapOnlyInOnePass) {
  // (1,0) is converted; (0,0) would be converted too if converted cells counted.
  const CostGrid aux = eaci::auxiliaryMap(sample(), Cell{3, 3}, Cell{0, 3});
  EXPECT_FALSE(aux.isBlocked(Cell{0, 0}));
}

TEST(AuxiliaryMap, NeverConvertsStartOrGoal) {
  const CostGrid aux = eaci::auxiliaryMap(sample(), Cell{2, 1}, Cell{1, 0});
  EXPECT_FALSE(aux.isBlocked(Cell{2, 1}));
  EXPECT_FALSE(aux.isBlocked(Cell{1, 0}));
}

TEST(AuxiliaryMap, OutsideTheMapIsFreeByDefaultAndAnObstacleOnRequest) {
  const CostGrid empty = CostGrid::fromRows({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, false);
  const CostGrid free_border = eaci::auxiliaryMap(empty, Cell{1, 1}, Cell{1, 2});
  EXPECT_FALSE(free_border.isBlocked(Cell{0, 0}));
  const CostGrid walled = eaci::auxiliaryMap(empty, Cell{1, 1}, Cell{1, 2}, eaci::AuxiliaryBorder::kObstacle);
  EXPECT_TRUE(walled.isBlocked(Cell{0, 0}));   // up and left are outside
  EXPECT_TRUE(walled.isBlocked(Cell{2, 2}));   // down and right
  EXPECT_FALSE(walled.isBlocked(Cell{0, 1}));  // only up is outside
}
