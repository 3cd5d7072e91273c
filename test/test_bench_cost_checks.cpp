// eaci_bench costs' route checks (src/bench/cost_checks.hpp) on maps small enough to check by
// hand: the cells a driven route crosses, its cost, the lethal and inscribed cells it enters
// and the independent weighted Dijkstra.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "../src/bench/cost_checks.hpp"
#include "eaci/search/astar.hpp"

using eaci::Cell;
using eaci::CellPath;
using eaci::CostGrid;
using eaci_bench::CostBytes;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

CostBytes bytes(int width, int height, std::vector<std::uint8_t> values) { return CostBytes{width, height, std::move(values)}; }

// The planners' reading of a costmap: >= 253 blocked, the rest weighted (neutral 50, factor 3).
CostGrid planningGrid(const CostBytes& b) {
  const eaci::GridView view(b.bytes.data(), b.width, b.height, eaci::RowOrder::kTopFirst,
                            eaci::CellInterpretation::costmap(253, false));
  return CostGrid::fromView(view, false);
}

// The map's own obstacles: the cells of cost 254.
CostGrid obstacleGrid(const CostBytes& b) {
  CostGrid grid(b.width, b.height, false);
  for (int r = 0; r < b.height; ++r)
    for (int c = 0; c < b.width; ++c) grid.setBlocked({r, c}, b.at({r, c}) >= 254);
  return grid;
}

}  // namespace

TEST(BenchCostChecks, DrivenCellsAreTheCellsEachSegmentCrosses) {
  EXPECT_EQ(eaci_bench::drivenCells({{0, 0}, {0, 3}}, false), (CellPath{{0, 0}, {0, 1}, {0, 2}, {0, 3}}));
  // A knight's move (2 columns, 1 row): column borders at t = 1/4, 3/4, the row border at t = 1/2.
  EXPECT_EQ(eaci_bench::drivenCells({{0, 0}, {1, 2}}, false), (CellPath{{0, 0}, {0, 1}, {1, 1}, {1, 2}}));
  // A diagonal crosses the cells on it and touches the two beside each corner it passes.
  EXPECT_EQ(eaci_bench::drivenCells({{0, 0}, {2, 2}}, false), (CellPath{{0, 0}, {1, 1}, {2, 2}}));
  EXPECT_EQ(eaci_bench::drivenCells({{0, 0}, {2, 2}}, true),
            (CellPath{{0, 0}, {0, 1}, {1, 0}, {1, 1}, {1, 2}, {2, 1}, {2, 2}}));
  // An 8-connected route is its own cells.
  const CellPath route{{0, 0}, {1, 1}, {1, 2}, {2, 2}};
  EXPECT_EQ(eaci_bench::drivenCells(route, false), route);
  EXPECT_TRUE(eaci_bench::drivenCells({}, false).empty());
}

TEST(BenchCostChecks, DrivenCostIsTheMoveCostOfAGridRouteAndTheSegmentCostOfAShortcut) {
  const CostBytes b = bytes(3, 1, {0, 50, 100});
  const CostGrid grid = planningGrid(b);
  // Moves into cost 50 and 100: (50 + 150) / 50 + (50 + 300) / 50 = 4 + 7.
  EXPECT_DOUBLE_EQ(eaci_bench::drivenCost(grid, {{0, 0}, {0, 1}, {0, 2}}), 11.0);
  EXPECT_DOUBLE_EQ(eaci::routeCost(grid, {{0, 0}, {0, 1}, {0, 2}}), 11.0);
  // The straight segment: half a cell of cost 0, a whole cell at factor 4, half a cell at factor 7.
  EXPECT_DOUBLE_EQ(eaci_bench::drivenCost(grid, {{0, 0}, {0, 2}}), 0.5 + 4.0 + 3.5);
}

TEST(BenchCostChecks, CountsLethalAndInscribedCellsTheRouteCrossesOrTouches) {
  // row 0: free; row 1: an inscribed cell (253) beside an obstacle (254); row 2: free.
  const CostBytes b = bytes(4, 3, {0, 0, 0, 0,  //
                                   0, 253, 254, 0,  //
                                   0, 0, 0, 0});
  const CostGrid planning = planningGrid(b), obstacles = obstacleGrid(b);

  // Along the top row: nothing lethal; nearest obstacle (1,2) is one row below (0,2).
  const auto top = eaci_bench::checkRoute(planning, obstacles, b, {{0, 0}, {0, 3}});
  EXPECT_EQ(top.lethal_cells, 0);
  EXPECT_EQ(top.inscribed_cells, 0);
  EXPECT_DOUBLE_EQ(top.min_clearance, 1.0);
  EXPECT_DOUBLE_EQ(top.mean_cell_cost, 0.0);
  EXPECT_DOUBLE_EQ(top.cost, 3.0);
  EXPECT_DOUBLE_EQ(top.length, 3.0);
  EXPECT_DOUBLE_EQ(top.turn_deg, 0.0);

  // The diagonal (0,0) -> (2,2) crosses the inscribed (1,1) and touches the obstacle (1,2).
  const auto diagonal = eaci_bench::checkRoute(planning, obstacles, b, {{0, 0}, {2, 2}});
  EXPECT_EQ(diagonal.lethal_cells, 1);
  EXPECT_EQ(diagonal.inscribed_cells, 1);
  EXPECT_EQ(diagonal.cost, kInf);  // not a route the planners may take
  EXPECT_DOUBLE_EQ(diagonal.min_clearance, 1.0);  // (1,1) is next to (1,2)

  // Down the left column and along the bottom: a 90 degree turn, clear of everything.
  const auto around = eaci_bench::checkRoute(planning, obstacles, b, {{0, 0}, {1, 0}, {2, 0}, {2, 1}});
  EXPECT_EQ(around.lethal_cells + around.inscribed_cells, 0);
  EXPECT_DOUBLE_EQ(around.turn_deg, 90.0);
  EXPECT_DOUBLE_EQ(around.cost, 3.0);
  EXPECT_DOUBLE_EQ(around.min_clearance, std::sqrt(2.0));  // (2,1) to (1,2)
}

TEST(BenchCostChecks, DijkstraByHand) {
  // 3 x 3 with an inscribed centre: no diagonal may pass beside it, so four straight moves.
  const CostBytes ring = bytes(3, 3, {0, 0, 0, 0, 253, 0, 0, 0, 0});
  EXPECT_DOUBLE_EQ(eaci_bench::dijkstraCost(ring, {0, 0}, {2, 2}), 4.0);
  const CostBytes open = bytes(3, 3, std::vector<std::uint8_t>(9, 0));
  EXPECT_DOUBLE_EQ(eaci_bench::dijkstraCost(open, {0, 0}, {2, 2}), 2.0 * std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(eaci_bench::dijkstraCost(bytes(3, 1, {0, 50, 100}), {0, 0}, {0, 2}), 11.0);
  // Walled off, or an end in a wall.
  EXPECT_EQ(eaci_bench::dijkstraCost(bytes(3, 1, {0, 254, 0}), {0, 0}, {0, 2}), kInf);
  EXPECT_EQ(eaci_bench::dijkstraCost(bytes(3, 1, {0, 0, 253}), {0, 0}, {0, 2}), kInf);
}

TEST(BenchCostChecks, DijkstraAgreesWithAStarOnRandomCostMaps) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> value(0, 299);
  for (int trial = 0; trial < 50; ++trial) {
    CostBytes b{17, 13, std::vector<std::uint8_t>(17 * 13)};
    for (auto& v : b.bytes) {
      const int x = value(rng);
      v = static_cast<std::uint8_t>(x < 40 ? 254 : x < 50 ? 253 : x % 253);
    }
    b.bytes.front() = 0;
    b.bytes.back() = 0;
    const eaci::CheapestPath a = eaci::cheapestPath(planningGrid(b), {0, 0}, {12, 16});
    const double d = eaci_bench::dijkstraCost(b, {0, 0}, {12, 16});
    if (!a.found) {
      EXPECT_EQ(d, kInf) << "trial " << trial;
      continue;
    }
    EXPECT_NEAR(a.cost, d, 1e-9 * d) << "trial " << trial;
  }
}
