// Stop checks inside the loops that grow with the map (include/eaci/parallel/stop_poll.hpp and
// every loop that ticks one): the check is called every StopPoll::kWorkBetweenChecks units of
// work, and once it says stop the plan ends with `interrupted` and a valid route or none.
// Work is counted by the calls of the check, never by the clock.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "eaci/aco/ant_walk.hpp"
#include "eaci/aco/colony_region.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/path/smoothing.hpp"
#include "eaci/planner.hpp"
#include "eaci/search/astar.hpp"
#include "test_support.hpp"

using eaci::Algorithm;
using eaci::Cell;
using eaci::CellPath;
using eaci::CostGrid;
using eaci::PlanStatus;
using eaci::StopPoll;

namespace {

constexpr std::size_t kEvery = StopPoll::kWorkBetweenChecks;

eaci::Parameters quickParameters() {
  eaci::Parameters p;
  p.ants = 4;
  p.max_iterations = 3;
  p.threads = 1;
  return p;
}

TEST(StopPoll, CallsTheCheckOnceEveryKWorkBetweenChecksUnitsAndLatches) {
  int calls = 0;
  int said_at = 0;
  const eaci::StopCheck check = [&](int iteration) {
    ++calls;
    said_at = iteration;
    return calls == 3;  // stop on the third call
  };
  StopPoll poll(check, 7);
  for (std::size_t k = 1; k < kEvery; ++k) ASSERT_FALSE(poll.tick());
  EXPECT_EQ(calls, 0);
  EXPECT_FALSE(poll.tick());  // unit 4096: the first call
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(said_at, 7);
  EXPECT_FALSE(poll.tick(kEvery));  // 4096 units at once: the second
  EXPECT_EQ(calls, 2);
  EXPECT_TRUE(poll.askNow());  // the third says stop
  EXPECT_TRUE(poll.tick());    // latched: no further call
  EXPECT_TRUE(poll.tick(10 * kEvery));
  EXPECT_TRUE(poll.askNow());
  EXPECT_EQ(calls, 3);
}

TEST(StopPoll, EmptyChecksNeverStopAndCheckWithoutArgumentsWork) {
  StopPoll none;
  EXPECT_FALSE(none.tick(100 * kEvery));
  EXPECT_FALSE(none.askNow());
  const eaci::StopCheck empty;
  StopPoll of_empty(empty);
  EXPECT_FALSE(of_empty.canStop());
  EXPECT_FALSE(of_empty.askNow());
  const std::function<bool()> no_argument = [] { return true; };
  StopPoll of_no_argument(no_argument);
  EXPECT_TRUE(of_no_argument.askNow());
  // A poll for another thread keeps the check and the latch, not the counter.
  StopPoll other = of_no_argument.forAnotherThread();
  EXPECT_TRUE(other.stopped());
}

// An open map of side x side cells.
CostGrid openGrid(int side) { return CostGrid(side, side, false); }

TEST(PlannerLimits, AStarStopsInsideTheSearchAndSaysSo) {
  // 300 x 300 cells with a wall down column 150 open only at the bottom row: from the top left
  // to the top right A* labels most of the left half (some 45000 cells) before it gets round,
  // far more than 2 x 4096. The check says stop on its second call: at the 8192nd cell.
  CostGrid grid = openGrid(300);
  for (int row = 0; row < 299; ++row) grid.setBlocked(Cell{row, 150}, true);
  int calls = 0;
  eaci::PlanOptions options;
  options.should_stop = [&](int) { return ++calls >= 2; };
  const auto r = eaci::plan(grid, Cell{0, 0}, Cell{0, 299}, Algorithm::kAStar, quickParameters(), options);
  EXPECT_EQ(r.status, PlanStatus::kStopped) << r.error;
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(calls, 2);
  // Without the stop the same plan gets round the wall.
  const auto full = eaci::plan(grid, Cell{0, 0}, Cell{0, 299}, Algorithm::kAStar, quickParameters());
  ASSERT_TRUE(full.success());
  EXPECT_FALSE(full.interrupted);
}

TEST(PlannerLimits, FloodBeforeTheColonyStopsInsideAndSaysSo) {
  // Classic ACO floods the map first to see that the goal can be reached: 200 x 200 = 40000
  // cells, the check is called at the 4096th and says stop.
  const CostGrid grid = openGrid(200);
  int calls = 0;
  eaci::PlanOptions options;
  options.should_stop = [&](int done) {
    ++calls;
    EXPECT_EQ(done, 0);  // set-up
    return true;
  };
  const auto r = eaci::plan(grid, Cell{0, 0}, Cell{199, 199}, Algorithm::kAco, quickParameters(), options);
  EXPECT_EQ(r.status, PlanStatus::kStopped) << r.error;
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(r.iterations_run, 0);
}

TEST(PlannerThreads, SearchThatMeetsInTheMiddleStopsOnBothSidesAndGivesNoRoute) {
  // 400 x 400 cells (over kTwoSidedSearchCells: geodesic islands use the two-sided search),
  // a wall with one gap at the far end makes both sides label tens of thousands of cells.
  // The check says stop from its first call on, from either side's thread.
  CostGrid grid = openGrid(400);
  for (int row = 0; row < 399; ++row) grid.setBlocked(Cell{row, 200}, true);
  std::atomic<int> calls{0};
  eaci::PlanOptions options;
  options.should_stop = [&](int) {
    calls.fetch_add(1);
    return true;
  };
  eaci::Parameters p = quickParameters();
  p.threads = 2;
  const auto r = eaci::plan(grid, Cell{0, 0}, Cell{0, 399}, Algorithm::kEaci, p, options);
  EXPECT_EQ(r.status, PlanStatus::kStopped) << r.error;
  EXPECT_TRUE(r.interrupted);
  EXPECT_FALSE(r.route_from_search);  // the search had not finished: no route to fall back on
  EXPECT_EQ(r.iterations_run, 0);
  // Each side asks once, at its 4096th cell, and both end there (the map has 160000 cells).
  EXPECT_GE(calls.load(), 1);
  EXPECT_LE(calls.load(), 2);
}

TEST(PlannerLimits, AntWalkStopsWithinKWorkBetweenChecksSteps) {
  // A corridor one cell high, 10000 long: the only walk takes 9999 steps. A check that says
  // stop ends it at the 4096th step, incomplete; a check that never does lets it arrive.
  const CostGrid grid(10000, 1, false);
  const std::vector<Cell> waypoints{Cell{0, 0}, Cell{0, 9999}};
  const eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  const eaci::WalkSetup setup(grid, field, waypoints, eaci::HeuristicRule::kGoalDistance, 1.0, 0.0);
  eaci::AntWalker walker;
  eaci::AntRoute route;
  eaci::SplitMix64 rng(1);
  const eaci::StopCheck never = [](int) { return false; };
  StopPoll keep_going(never);
  walker.walk(setup, rng, route, &keep_going);
  EXPECT_TRUE(route.complete);
  EXPECT_EQ(route.cells.size(), 10000u);
  const eaci::StopCheck always = [](int) { return true; };
  StopPoll stop(always);
  walker.walk(setup, rng, route, &stop);
  EXPECT_FALSE(route.complete);
  EXPECT_EQ(route.cells.size(), kEvery);  // the start and 4095 steps
}

TEST(PlannerLimits, SmoothingStoppedReturnsAValidRoute) {
  // A staircase of 3000 cells on an open map smooths into one segment. Stopped at its first
  // check, it returns the route as it was: the tries from the first cell walk about 2 j cells
  // for the shortcut to cell j, 4096 add up at j = 64 (64 x 65 - 2), long before that first
  // shortcut ends; what was not smoothed follows cell by cell.
  const CostGrid grid = openGrid(1600);
  CellPath route;
  for (int k = 0; k < 1500; ++k) {
    route.push_back(Cell{k, k});
    route.push_back(Cell{k, k + 1});
  }
  EXPECT_EQ(eaci::smoothRoute(grid, route), (CellPath{route.front(), route.back()}));
  const eaci::StopCheck always = [](int) { return true; };
  StopPoll stop(always);
  EXPECT_EQ(eaci::smoothRoute(grid, route, &stop), route);
  EXPECT_TRUE(stop.stopped());
  // A serpentine: corridors 40 cells long joined at alternate ends. The tries from a corner
  // end at the next turn (about 40 x 41 / 2 cells spanned for the 40 of a corridor), so the
  // second check (8192 cells) comes some ten corridors in: those are smoothed, the
  // rest of the route is its own cells.
  CostGrid serpentine(42, 41, false);
  for (int row = 1; row < 41; row += 2)
    for (int col = 0; col < 42; ++col)
      serpentine.setBlocked(Cell{row, col}, !(col == (row % 4 == 1 ? 41 : 0)));
  const CellPath winding = eaci::cheapestPath(serpentine, Cell{0, 0}, Cell{40, 0}).path;
  ASSERT_GT(winding.size(), 800u);
  int calls = 0;
  const eaci::StopCheck second = [&](int) { return ++calls >= 2; };
  StopPoll later(second);
  const CellPath partial = eaci::smoothRoute(serpentine, winding, &later);
  ASSERT_TRUE(later.stopped());
  ASSERT_GT(partial.size(), 5u);
  ASSERT_LT(partial.size(), winding.size() - 100);
  EXPECT_EQ(partial.front(), winding.front());
  EXPECT_EQ(partial.back(), winding.back());
  EXPECT_LT(partial.size(), winding.size());
  // Every corner-to-corner segment is free, and the corners are cells of the route, in order.
  std::size_t at = 0;
  for (std::size_t k = 0; k < partial.size(); ++k) {
    while (at < winding.size() && !(winding[at] == partial[k])) ++at;
    ASSERT_LT(at, winding.size()) << "corner " << k << " is not a cell of the route, in order";
    if (k > 0) {
      EXPECT_TRUE(std::isfinite(eaci::segmentCost(serpentine, partial[k - 1], partial[k])));
    }
  }
  // Its tail is the route's own cells: the last 100 cells of both are the same.
  EXPECT_TRUE(std::equal(winding.end() - 100, winding.end(), partial.end() - 100));
}

TEST(PlannerLimits, ColonyRegionStopsInsideAndWholeMapRegionToo) {
  const CostGrid grid = openGrid(300);
  CellPath route;
  for (int k = 0; k < 300; ++k) route.push_back(Cell{k, k});
  int calls = 0;
  const eaci::StopCheck second = [&](int) { return ++calls >= 2; };
  StopPoll poll(second);
  eaci::ColonyRegion::aroundRoute(grid, route, 40, eaci::ColonyRegion{}, std::numeric_limits<std::size_t>::max(), &poll);
  EXPECT_TRUE(poll.stopped());
  EXPECT_EQ(calls, 2);
  calls = 0;
  StopPoll whole(second);
  eaci::ColonyRegion::wholeMap(grid, eaci::ColonyRegion{}, &whole);  // 90000 cells, a row of 300 a tick
  EXPECT_TRUE(whole.stopped());
  EXPECT_EQ(calls, 2);
}

TEST(PlannerLimits, NothingStoppedKeepsThePaperRoutesOfAPlanWithAStopCheck) {
  // A stop check that never says stop changes nothing: the same route and iterations as
  // without one (the paper's 20 x 20 map, EACI, seed 1).
  const CostGrid grid = eaci::test::paperMap("paper-20x20.txt", true);
  eaci::Parameters p;
  p.seed = 1;
  p.max_iterations = 20;
  eaci::PlanOptions options;
  int calls = 0;
  options.should_stop = [&](int) {
    ++calls;
    return false;
  };
  const auto with_check = eaci::plan(grid, Cell{0, 0}, Cell{19, 19}, Algorithm::kEaci, p, options);
  const auto without = eaci::plan(grid, Cell{0, 0}, Cell{19, 19}, Algorithm::kEaci, p);
  ASSERT_TRUE(with_check.success());
  EXPECT_GT(calls, 0);
  EXPECT_EQ(with_check.path, without.path);
  EXPECT_EQ(with_check.best_cost_so_far, without.best_cost_so_far);
  EXPECT_FALSE(with_check.interrupted);
}

}  // namespace
