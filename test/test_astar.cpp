// The exact reference: A* and the Dijkstra field against hand cases and the published optima.
#include <gtest/gtest.h>

#include <cmath>

#include "eaci/aco/leg_cost_field.hpp"
#include "eaci/search/astar.hpp"
#include "test_support.hpp"

using eaci::CostGrid;
using eaci::Cell;

TEST(AStar, CornerRuleDecidesTheWayPastADiagonalGap) {
  // Centre obstacle: with corner cutting (0,1) -> (1,2) slips past it: 2 + sqrt2.
  const std::vector<std::vector<int>> rows = {{0, 0, 0}, {0, 1, 0}, {0, 0, 0}};
  const auto cutting = eaci::cheapestPath(CostGrid::fromRows(rows, true), Cell{0, 0}, Cell{2, 2});
  ASSERT_TRUE(cutting.found);
  EXPECT_NEAR(cutting.length, 2.0 + std::sqrt(2.0), 1e-12);
  const auto strict = eaci::cheapestPath(CostGrid::fromRows(rows, false), Cell{0, 0}, Cell{2, 2});
  ASSERT_TRUE(strict.found);
  EXPECT_NEAR(strict.length, 4.0, 1e-12);
  EXPECT_EQ(eaci::test::routeDefect(CostGrid::fromRows(rows, false), strict.path, Cell{0, 0}, Cell{2, 2}), "");
}

TEST(AStar, DiagonalBetweenTwoTouchingObstacles) {
  const std::vector<std::vector<int>> rows = {{0, 1}, {1, 0}};
  EXPECT_TRUE(eaci::cheapestPath(CostGrid::fromRows(rows, true), Cell{0, 0}, Cell{1, 1}).found);
  EXPECT_FALSE(eaci::cheapestPath(CostGrid::fromRows(rows, false), Cell{0, 0}, Cell{1, 1}).found);
}

TEST(AStar, EmptyMapLengthIsTheOctileDistance) {
  const CostGrid grid = CostGrid::fromRows(std::vector<std::vector<int>>(6, std::vector<int>(9, 0)), false);
  const auto p = eaci::cheapestPath(grid, Cell{5, 0}, Cell{1, 8});
  ASSERT_TRUE(p.found);
  EXPECT_NEAR(p.length, 4 * std::sqrt(2.0) + 4, 1e-12);
  EXPECT_NEAR(eaci::test::countedLength(p.path), p.length, 1e-12);
}

TEST(AStar, UnreachableBlockedOrOffMapGivesNoPath) {
  const CostGrid grid = CostGrid::fromRows({{0, 1, 0}, {0, 1, 0}, {0, 1, 0}}, true);
  EXPECT_FALSE(eaci::cheapestPath(grid, Cell{0, 0}, Cell{0, 2}).found);
  EXPECT_FALSE(eaci::cheapestPath(grid, Cell{0, 0}, Cell{0, 1}).found);
  EXPECT_FALSE(eaci::cheapestPath(grid, Cell{0, 0}, Cell{5, 5}).found);
}

TEST(AStar, GivesThePublishedOptimaOfThePaperMaps) {
  for (const auto& pc : eaci::test::paperCases()) {
    for (bool cutting : {true, false}) {
      const CostGrid grid = eaci::test::paperMap(pc.file, cutting);
      const auto p = eaci::cheapestPath(grid, pc.start, pc.goal);
      const double expected = cutting ? pc.optimum_cutting : pc.optimum_no_cutting;
      if (expected < 0) {
        EXPECT_FALSE(p.found) << pc.file;
        continue;
      }
      ASSERT_TRUE(p.found) << pc.file;
      EXPECT_NEAR(p.length, expected, 1e-4) << pc.file << (cutting ? " cutting" : " no cutting");
      EXPECT_EQ(eaci::test::routeDefect(grid, p.path, pc.start, pc.goal), "") << pc.file;
      EXPECT_NEAR(eaci::test::countedLength(p.path), p.length, 1e-9);
    }
  }
}

TEST(AStar, LegCostFieldAgreesWithAStar) {
  // The backward search of the islands' leg fields, over the whole map: the route from corner
  // to corner spans every row and column, so the field's window is the whole map.
  const CostGrid grid = eaci::test::paperMap("paper-30x30.txt", true);
  const auto route = eaci::cheapestPath(grid, Cell{29, 0}, Cell{0, 29});
  ASSERT_TRUE(route.found);
  const eaci::LegCostField field(grid, route.path, Cell{0, 29});
  EXPECT_NEAR(field.at(Cell{29, 0}), 44.5269, 1e-4);
  EXPECT_DOUBLE_EQ(field.at(Cell{0, 29}), 0.0);
  int reached = 0;
  for (int r = 0; r < 30; r += 7)
    for (int c = 0; c < 30; c += 5) {
      const auto p = eaci::cheapestPath(grid, Cell{r, c}, Cell{0, 29});
      if (!p.found) continue;
      ++reached;
      EXPECT_NEAR(field.at(Cell{r, c}), p.length, 1e-9) << r << "," << c;
    }
  EXPECT_GE(reached, 15);  // most of the 30 cells sampled: the comparison is not vacuous
}
