// Eq. 13-15: island selection on maps where the order can be worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "eaci/aco/auxiliary_map.hpp"
#include "eaci/aco/islands.hpp"
#include "eaci/search/reachability.hpp"
#include "eaci/search/astar.hpp"
#include "test_support.hpp"

using eaci::CostGrid;
using eaci::Cell;

namespace {
std::vector<Cell> islandsOn(const CostGrid& grid, Cell s, Cell e, int n) {
  const CostGrid aux = eaci::auxiliaryMap(grid, s, e);
  return eaci::paperIslands(aux, eaci::reachableFrom(grid, s), s, e, n);
}
CostGrid emptyGrid(int rows, int cols) {
  return CostGrid::fromRows(std::vector<std::vector<int>>(rows, std::vector<int>(cols, 0)), false);
}
}  // namespace

TEST(Islands, SearchRadiusIsDistanceOverNMinusOne) {
  EXPECT_DOUBLE_EQ(eaci::searchRadius(Cell{0, 0}, Cell{0, 9}, 4), 3.0);
  EXPECT_NEAR(eaci::searchRadius(Cell{0, 0}, Cell{19, 19}, 9), 19 * std::sqrt(2.0) / 8, 1e-12);
}

TEST(Islands, ScoreIsSumOfDistancesToStartAndGoal) {
  EXPECT_DOUBLE_EQ(eaci::islandScore(Cell{0, 3}, Cell{0, 0}, Cell{0, 9}), 9.0);
  EXPECT_DOUBLE_EQ(eaci::islandScore(Cell{4, 0}, Cell{0, 0}, Cell{0, 3}), 4.0 + 5.0);
}

TEST(Islands, EvenlySpacedOnAStraightCorridor) {
  // r_s = 9 / 3 = 3; every cell on SE ties at D = 9; ties go to the cell nearest E.
  EXPECT_EQ(islandsOn(emptyGrid(1, 10), Cell{0, 0}, Cell{0, 9}, 4),
            (std::vector<Cell>{{0, 0}, {0, 3}, {0, 6}, {0, 9}}));
}

TEST(Islands, EvenlySpacedOnTheDiagonalOfAnEmptyMap) {
  // r_s = 9 sqrt2 / 3 = 3 sqrt2: (3,3) lies exactly on the circle.
  EXPECT_EQ(islandsOn(emptyGrid(10, 10), Cell{0, 0}, Cell{9, 9}, 4),
            (std::vector<Cell>{{0, 0}, {3, 3}, {6, 6}, {9, 9}}));
}

TEST(Islands, StepOverAnObstacleOnTheLineAndMayExceedN) {
  // 7 x 7, obstacle at (3,3), S = (3,0), E = (3,6), N = 3: r_s = 3.
  // From S the on-line cells (3,1), (3,2) tie at D = 6 -> (3,2), nearer E. From (3,2),
  // (3,5) is within 3, on the line and nearest E. Then E is within r_s.
  CostGrid grid = emptyGrid(7, 7);
  grid.setBlocked(Cell{3, 3}, true);
  EXPECT_EQ(islandsOn(grid, Cell{3, 0}, Cell{3, 6}, 3),
            (std::vector<Cell>{{3, 0}, {3, 2}, {3, 5}, {3, 6}}));
}

TEST(Islands, NeverInAPocketThatCannotBeReachedFromStart) {
  // A 3 x 3 free pocket sealed by a ring (rows 0-4, cols 3-7) sits on the straight line.
  CostGrid grid = emptyGrid(7, 11);
  for (int c = 3; c <= 7; ++c) {
    grid.setBlocked(Cell{0, c}, true);
    grid.setBlocked(Cell{4, c}, true);
  }
  for (int r = 1; r <= 3; ++r) {
    grid.setBlocked(Cell{r, 3}, true);
    grid.setBlocked(Cell{r, 7}, true);
  }
  const Cell s{2, 0}, e{2, 10};
  const auto islands = islandsOn(grid, s, e, 3);
  // Without the reachability rule (2,5) would win: on the line, exactly r_s = 5 away.
  ASSERT_GE(islands.size(), 3u);
  EXPECT_EQ(islands[1], (Cell{2, 2}));
  for (const Cell& c : islands) {
    const bool in_pocket = c.row >= 1 && c.row <= 3 && c.col >= 4 && c.col <= 6;
    EXPECT_FALSE(in_pocket) << "island (" << c.row << "," << c.col << ") is in the sealed pocket";
  }
  EXPECT_EQ(islands.front(), s);
  EXPECT_EQ(islands.back(), e);
}

TEST(Islands, AdvanceStrictlyTowardTheGoalAndEndAtIt) {
  for (const auto& pc : eaci::test::paperCases()) {
    const CostGrid grid = eaci::test::paperMap(pc.file, true);
    for (int n : {2, 3, 6, 9, 12}) {
      const auto islands = islandsOn(grid, pc.start, pc.goal, n);
      ASSERT_GE(islands.size(), 2u);
      EXPECT_EQ(islands.front(), pc.start);
      EXPECT_EQ(islands.back(), pc.goal);
      for (std::size_t k = 1; k + 1 < islands.size(); ++k) {
        EXPECT_LT(eaci::euclidean(islands[k], pc.goal), eaci::euclidean(islands[k - 1], pc.goal)) << pc.file;
        EXPECT_LE(eaci::euclidean(islands[k], islands[k - 1]), eaci::searchRadius(pc.start, pc.goal, n) + 1e-9);
        EXPECT_TRUE(grid.isFree(islands[k]));
      }
    }
  }
}

TEST(Islands, PaperFortyMapGivesThePapersLength) {
  // The spec's reading reproduces the paper's 40x40 EACI figure: with N = 9, 11 islands, and
  // the shortest route through them is 59.2548 = 58.0833 + 2(2 - sqrt2). With N = 6 the
  // islands differ (7 of them) but the route through them is 59.2548 as well.
  const CostGrid grid = eaci::test::paperMap("paper-40x40.txt", true);
  for (int n : {6, 9}) {
    const auto islands = islandsOn(grid, Cell{0, 0}, Cell{39, 39}, n);
    if (n == 9) {
      EXPECT_EQ(islands.size(), 11u);
    }
    double through = 0.0;
    for (std::size_t k = 0; k + 1 < islands.size(); ++k)
      through += eaci::cheapestPath(grid, islands[k], islands[k + 1]).length;
    EXPECT_NEAR(through, 59.2548, 1e-4) << "N = " << n;
  }
}
