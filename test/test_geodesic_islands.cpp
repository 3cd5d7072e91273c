// Geodesic islands (beyond the paper): on a shortest route, r_s apart, with exact leg costs.
#include <gtest/gtest.h>

#include <cmath>

#include "eaci/aco/geodesic_islands.hpp"
#include "eaci/aco/leg_cost_field.hpp"
#include "eaci/aco/solvers.hpp"
#include "eaci/planner/parameters.hpp"
#include "eaci/search/astar.hpp"
#include "test_support.hpp"

using eaci::CostGrid;
using eaci::Cell;
using eaci::CellPath;

namespace {
CostGrid emptyGrid(int rows, int cols) {
  return CostGrid::fromRows(std::vector<std::vector<int>>(rows, std::vector<int>(cols, 0)), false);
}

// Geodesic islands (the default strategy) with N islands and r_s not capped: Eq. 13's spacing.
eaci::Parameters geodesicWithoutCap(int islands) {
  eaci::Parameters params;
  params.island_strategy = eaci::IslandStrategy::kGeodesic;
  params.islands = islands;
  params.island_spacing_max = 0.0;
  return params;
}
}  // namespace

TEST(GeodesicIslands, SitOnAShortestRoute) {
  for (const auto& pc : eaci::test::paperCases()) {
    const CostGrid grid = eaci::test::paperMap(pc.file, true);
    const eaci::IslandPlan plan = eaci::planIslands(grid, pc.start, pc.goal, geodesicWithoutCap(9));
    EXPECT_EQ(eaci::test::routeDefect(grid, plan.route, pc.start, pc.goal), "") << pc.file;
    EXPECT_NEAR(eaci::test::countedLength(plan.route), pc.optimum_cutting, 1e-4) << pc.file;
    EXPECT_NEAR(plan.route_cost, pc.optimum_cutting, 1e-4) << pc.file;  // a binary map: the cost is the length
  }
}

TEST(GeodesicIslands, NoneWhenTheGoalCannotBeReached) {
  const CostGrid grid = CostGrid::fromRows({{0, 1, 0}}, false);
  const eaci::IslandPlan plan = eaci::planIslands(grid, Cell{0, 0}, Cell{0, 2}, geodesicWithoutCap(9));
  EXPECT_TRUE(plan.route.empty());
  EXPECT_TRUE(plan.islands.empty());
}

TEST(GeodesicIslands, SpacedRsApartAlongTheRoute) {
  // Corridor of 10 cells, N = 4: r_s = 9 / 3 = 3, islands at 3 and 6, then E (3 further) is within r_s.
  const CostGrid grid = emptyGrid(1, 10);
  const eaci::IslandPlan plan = eaci::planIslands(grid, Cell{0, 0}, Cell{0, 9}, geodesicWithoutCap(4));
  EXPECT_EQ(plan.islands, (std::vector<Cell>{{0, 0}, {0, 3}, {0, 6}, {0, 9}}));
}

TEST(GeodesicIslands, SkipCellsTheAuxiliaryMapBlocks) {
  // Same corridor, but the auxiliary map blocks (0,3): the island moves on to (0,4), the next
  // one r_s after it to (0,7), and E is within r_s of (0,7).
  CellPath corridor;
  for (int c = 0; c < 10; ++c) corridor.push_back(Cell{0, c});
  const auto free_on_auxiliary = [](Cell c) { return !(c == Cell{0, 3}); };
  EXPECT_EQ(eaci::geodesicIslands(free_on_auxiliary, corridor, Cell{0, 0}, Cell{0, 9}, 4),
            (std::vector<Cell>{{0, 0}, {0, 4}, {0, 7}, {0, 9}}));
}

TEST(GeodesicIslands, RouteThroughTheIslandsIsTheOptimum) {
  for (const auto& pc : eaci::test::paperCases()) {
    const CostGrid grid = eaci::test::paperMap(pc.file, true);
    const auto islands = eaci::planIslands(grid, pc.start, pc.goal, geodesicWithoutCap(9)).islands;
    ASSERT_GE(islands.size(), 3u);
    double through = 0.0;
    for (std::size_t k = 0; k + 1 < islands.size(); ++k)
      through += eaci::cheapestPath(grid, islands[k], islands[k + 1]).length;
    EXPECT_NEAR(through, pc.optimum_cutting, 1e-4) << pc.file;
  }
}

TEST(LegCostField, ExactInsideTheWindowAndNeverBetterOutside) {
  // 12 x 12 open map with a wall; the island at (6,9), a leg from (6,2).
  CostGrid grid = emptyGrid(12, 12);
  for (int r = 3; r <= 9; ++r) grid.setBlocked(Cell{r, 6}, true);
  const CellPath leg = {{6, 2}, {5, 3}, {4, 4}, {3, 5}, {2, 6}, {3, 7}, {4, 8}, {5, 9}, {6, 9}};
  const eaci::LegCostField field(grid, leg, Cell{6, 9});
  EXPECT_DOUBLE_EQ(field.at(Cell{6, 9}), 0.0);
  EXPECT_NEAR(field.at(Cell{6, 8}), 1.0, 1e-12);
  // The window is rows 0-10 (the leg's rows 2-6, margin 4), all columns: inside it the
  // values are the exact grid distances, around the wall too.
  for (Cell c : {Cell{6, 5}, Cell{9, 5}, Cell{2, 2}, Cell{10, 11}}) {
    const double exact = eaci::cheapestPath(grid, c, Cell{6, 9}).length;
    EXPECT_NEAR(field.at(c), exact, 1e-9) << c.row << "," << c.col;
  }
  // Row 11 is outside: it reads as at least one more than anything inside.
  EXPECT_GT(field.at(Cell{11, 11}), field.at(Cell{0, 0}));
}

TEST(LegCostField, CellsOutsideTheWindowReadAsFarAway) {
  const CostGrid grid = emptyGrid(40, 40);
  const CellPath leg = {{20, 20}, {20, 21}, {20, 22}};
  const eaci::LegCostField field(grid, leg, Cell{20, 22});
  // The window is the leg plus a margin of kMinWindowMargin (1): (20, 30) lies outside it.
  static_assert(eaci::LegCostField::kMinWindowMargin == 1, "the cells below assume a margin of 1");
  const double outside = field.at(Cell{20, 30});
  EXPECT_GE(outside, 8.0);                     // at least the straight-line distance
  EXPECT_GT(outside, field.at(Cell{20, 23}));  // the window's edge, 1 away
  EXPECT_NEAR(field.at(Cell{20, 23}), 1.0, 1e-12);
  EXPECT_NEAR(field.at(Cell{21, 23}), std::sqrt(2.0), 1e-12);  // the window's corner
  EXPECT_GT(field.at(Cell{20, 24}), field.at(Cell{21, 23}));   // just outside reads costlier than any cell inside
}
