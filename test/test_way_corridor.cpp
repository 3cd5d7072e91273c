// The way and the route within it (Parameters::way_cost_factor, grid/way_corridor.hpp): the way
// is chosen by one weighting of the costs, the route's shape within its corridor by another.
// Expectations by hand: move costs step x (50 + cost_factor x c) / 50.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

#include "eaci/grid/way_corridor.hpp"
#include "eaci/planner.hpp"
#include "test_support.hpp"

namespace {

using eaci::Algorithm;
using eaci::Cell;
using eaci::CellPath;
using eaci::CostGrid;

bool passes(const CellPath& path, Cell cell) {
  for (const Cell& c : path)
    if (c == cell) return true;
  return false;
}

// The route's largest distance, in rows, from row `row` (the ways below run along one row).
int widestStray(const CellPath& path, int row) {
  int widest = 0;
  for (const Cell& c : path) widest = std::max(widest, std::abs(c.row - row));
  return widest;
}

eaci::Parameters exactRoutes(double way_cost_factor, int way_corridor) {
  eaci::Parameters p;
  p.way_cost_factor = way_cost_factor;
  p.way_corridor = way_corridor;
  return p;
}

// 21 x 13 cells, a wall down column 10 with two openings: A, rows 5-7, on the straight line from
// S (6, 2) to E (6, 18), its cells of cost 100; B, rows 0-2, free. Through A the cheapest route
// is row 6, 15 free moves and one into (6, 10): 15 + (50 + 100 f) / 50, 22 at cost_factor 3 and
// 18 at 1. Through B: twice the octile distance from S to row 2, 2 (4 + 4 sqrt 2) = 19.31.
CostGrid twoOpenings() {
  CostGrid grid(21, 13, false);
  for (int row = 0; row < 13; ++row) grid.setBlocked(Cell{row, 10}, !(row <= 2 || (row >= 5 && row <= 7)));
  for (int row = 5; row <= 7; ++row) grid.setCost(Cell{row, 10}, 100);
  return grid;
}

// 17 x 13 free cells with a blob of cost 50 at rows 5-7, columns 7-9, across the straight line
// from S (6, 0) to E (6, 16). Straight through it: 13 + 3 (50 + 50 f) / 50, 16.3 at
// cost_factor 0.1 and 25 at 3. Round it, two rows off the line and back: 12 + 4 sqrt 2 = 17.66.
CostGrid blobOnTheLine() {
  CostGrid grid(17, 13, false);
  for (int row = 5; row <= 7; ++row)
    for (int col = 7; col <= 9; ++col) grid.setCost(Cell{row, col}, 50);
  return grid;
}

TEST(WayCorridor, BlocksEveryCellFartherThanTheRadiusAndKeepsTheRest) {
  CostGrid grid(7, 7, false);
  grid.setBlocked(Cell{3, 1}, true);
  grid.setCost(Cell{3, 4}, 40);
  const CostGrid corridor = eaci::wayCorridor(grid, CellPath{Cell{3, 3}}, 2);
  int open = 0;
  for (int row = 0; row < 7; ++row)
    for (int col = 0; col < 7; ++col) open += !corridor.isBlocked(Cell{row, col});
  EXPECT_EQ(open, 12);  // the 13 cells with dr^2 + dc^2 <= 4, less the obstacle among them
  EXPECT_TRUE(corridor.isBlocked(Cell{3, 1}));   // an obstacle stays one
  EXPECT_EQ(corridor.cost(Cell{3, 4}), 40);      // a cell inside keeps its cost
  EXPECT_FALSE(corridor.isBlocked(Cell{1, 3}));  // 2 away
  EXPECT_TRUE(corridor.isBlocked(Cell{1, 2}));   // sqrt 5 away
  EXPECT_TRUE(corridor.isBlocked(Cell{0, 0}));
  EXPECT_EQ(grid.cost(Cell{0, 0}), 0);  // the grid itself is untouched
}

TEST(WayCorridor, TheWayIsChosenByWayCostFactorAndPricedByCostFactor) {
  const CostGrid grid = twoOpenings();
  const Cell start{6, 2}, goal{6, 18};
  const auto one_weighting = eaci::plan(grid, start, goal, Algorithm::kAStar, exactRoutes(0.0, 3));
  ASSERT_TRUE(one_weighting.success()) << one_weighting.error;
  EXPECT_NEAR(one_weighting.cost, 8 + 8 * std::sqrt(2.0), 1e-9);  // through B
  EXPECT_TRUE(one_weighting.way.empty());

  const auto within_way = eaci::plan(grid, start, goal, Algorithm::kAStar, exactRoutes(1.0, 3));
  ASSERT_TRUE(within_way.success()) << within_way.error;
  EXPECT_TRUE(passes(within_way.way, Cell{6, 10}));  // at cost_factor 1, A (18) beats B (19.31)
  EXPECT_TRUE(passes(within_way.path, Cell{6, 10}));
  EXPECT_NEAR(within_way.cost, 22.0, 1e-9);  // the route's cost is still cost_factor 3's
  EXPECT_EQ(eaci::test::routeDefect(grid, within_way.path, start, goal), "");
}

TEST(WayCorridor, TheRouteTakesItsShapeFromCostFactorWithinTheCorridor) {
  const CostGrid grid = blobOnTheLine();
  const Cell start{6, 0}, goal{6, 16};
  // At cost_factor 0.1 the way runs straight through the blob (16.3 against 17.66); within two
  // rows of it cost_factor 3 goes round (17.66 against 25).
  const auto round_it = eaci::plan(grid, start, goal, Algorithm::kAStar, exactRoutes(0.1, 2));
  ASSERT_TRUE(round_it.success()) << round_it.error;
  EXPECT_EQ(widestStray(round_it.way, 6), 0);
  EXPECT_NEAR(round_it.cost, 12 + 4 * std::sqrt(2.0), 1e-9);
  EXPECT_LE(widestStray(round_it.path, 6), 2);
  // Within one row there is no way round: through the blob, 25.
  const auto held = eaci::plan(grid, start, goal, Algorithm::kAStar, exactRoutes(0.1, 1));
  ASSERT_TRUE(held.success()) << held.error;
  EXPECT_NEAR(held.cost, 25.0, 1e-9);
  EXPECT_LE(widestStray(held.path, 6), 1);
}

TEST(WayCorridor, TheColonyWalksWithinTheCorridorToo) {
  const CostGrid grid = twoOpenings();
  eaci::Parameters p = exactRoutes(1.0, 3);
  for (unsigned seed = 1; seed <= 5; ++seed) {
    p.seed = seed;
    const auto r = eaci::plan(grid, Cell{6, 2}, Cell{6, 18}, Algorithm::kEaci, p);
    ASSERT_TRUE(r.success()) << r.error;
    EXPECT_LE(widestStray(r.path, 6), 3) << "seed " << seed;  // never through B, 4 rows off
    EXPECT_EQ(eaci::test::routeDefect(grid, r.path, Cell{6, 2}, Cell{6, 18}), "") << "seed " << seed;
  }
}

TEST(WayCorridor, TurnsArePricedInTheWayAsInTheRoute) {
  // With turn_cost the way is the heading search's optimum at way_cost_factor: on the blob map
  // at turn_cost 1 going round turns pi (4 x 45 deg) more than the straight line, so even at
  // cost_factor 3 the route stays straight inside a one-row corridor: 25, no turn.
  eaci::Parameters p = exactRoutes(0.1, 1);
  p.turn_cost = 1.0;
  const auto r = eaci::plan(blobOnTheLine(), Cell{6, 0}, Cell{6, 16}, Algorithm::kAStar, p);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_NEAR(r.combined_cost, 25.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.total_turn_deg, 0.0);
}

TEST(WayCorridor, NoRouteStopAndBadValuesSaySo) {
  CostGrid walled(9, 5, false);
  for (int row = 0; row < 5; ++row) walled.setBlocked(Cell{row, 4}, true);
  const auto none = eaci::plan(walled, Cell{2, 0}, Cell{2, 8}, Algorithm::kEaci, exactRoutes(1.0, 3));
  EXPECT_EQ(none.status, eaci::PlanStatus::kNoPath) << none.error;
  EXPECT_EQ(none.algorithm, Algorithm::kEaci);

  eaci::PlanOptions stop_now;
  stop_now.should_stop = [](int) { return true; };
  const auto stopped =
      eaci::plan(twoOpenings(), Cell{6, 2}, Cell{6, 18}, Algorithm::kEaci, exactRoutes(1.0, 3), stop_now);
  EXPECT_EQ(stopped.status, eaci::PlanStatus::kStopped) << stopped.error;
  EXPECT_NE(stopped.error.find("way"), std::string::npos) << stopped.error;

  for (double bad : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_NE(eaci::validationError(exactRoutes(bad, 16)).find("way_cost_factor"), std::string::npos) << bad;
  for (int bad : {0, 101})
    EXPECT_NE(eaci::validationError(exactRoutes(1.0, bad)).find("way_corridor"), std::string::npos) << bad;
  EXPECT_EQ(eaci::validationError(exactRoutes(0.0, 16)), "");
}

}  // namespace
