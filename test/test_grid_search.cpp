// The grid search (searchGrid and GridSearchWorkspace) against an independent, straightforward
// Dijkstra written with CostGrid's own move rule and move costs (canMove, moveCost), on random
// cost maps with several cost rules (one steep enough to spread priorities far apart), corner
// rules, windows, targets and reversed costs; one workspace serves maps of every size in turn.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <utility>
#include <vector>

#include "eaci/search/astar.hpp"
#include "test_support.hpp"

using eaci::Cell;
using eaci::CellWindow;
using eaci::CostGrid;
using eaci::GridSearchRequest;
using eaci::GridSearchResult;
using eaci::GridSearchWorkspace;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Route costs from `source` to every cell of the window (reverse: from every cell to `source`),
// by grid index; routes stay inside the window.
std::vector<double> referenceCosts(const CostGrid& grid, const CellWindow& window, Cell source, bool reverse) {
  std::vector<double> cost(grid.cellCount(), kInf);
  if (!grid.isFree(source) || !window.contains(source)) return cost;
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  cost[grid.index(source)] = 0.0;
  open.push({0.0, grid.index(source)});
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > cost[i]) continue;
    const Cell here = grid.cellAt(i);
    for (int dir = 0; dir < eaci::kDirections; ++dir) {
      const Cell next = eaci::step(here, dir);
      if (!window.contains(next) || !grid.isFree(next)) continue;
      // Reverse: the move next -> here, in the opposite direction.
      const int back = (dir + 4) % eaci::kDirections;
      if (reverse ? !grid.canMove(next, back) : !grid.canMove(here, dir)) continue;
      const double g = d + (reverse ? grid.moveCost(next, back) : grid.moveCost(here, dir));
      if (g < cost[grid.index(next)]) {
        cost[grid.index(next)] = g;
        open.push({g, grid.index(next)});
      }
    }
  }
  return cost;
}

CostGrid randomGrid(std::mt19937& rng, int width, int height) {
  const eaci::CostRule rules[] = {{50.0, 3.0}, {50.0, 0.2}, {1.0, 10.0}};  // the last: moves up to 2 500 x
  CostGrid grid(width, height, rng() % 2 == 0, rules[rng() % 3]);
  const int blocked_percent = static_cast<int>(rng() % 35);
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      const int roll = static_cast<int>(rng() % 100);
      if (roll < blocked_percent) grid.setBlocked(Cell{r, c}, true);
      else if (roll >= 70) grid.setCost(Cell{r, c}, static_cast<std::uint8_t>(rng() % 255));
    }
  }
  return grid;
}

Cell randomCell(std::mt19937& rng, const CostGrid& grid) {
  return Cell{static_cast<int>(rng() % static_cast<unsigned>(grid.height())),
              static_cast<int>(rng() % static_cast<unsigned>(grid.width()))};
}

CellWindow randomWindow(std::mt19937& rng, const CostGrid& grid) {
  if (rng() % 3 == 0) return CellWindow::whole(grid);
  const Cell corner = randomCell(rng, grid);
  return CellWindow{corner.row, corner.col, 1 + static_cast<int>(rng() % static_cast<unsigned>(grid.height() - corner.row)),
                    1 + static_cast<int>(rng() % static_cast<unsigned>(grid.width() - corner.col))};
}

double tolerance(double cost) { return 1e-9 * std::max(1.0, cost); }

}  // namespace

TEST(GridSearch, DistancesEqualAnIndependentDijkstraOnRandomCostMaps) {
  GridSearchWorkspace workspace;  // one for every map: sizes grow and shrink
  int compared_routes = 0;
  for (std::uint32_t seed = 1; seed <= 60; ++seed) {
    std::mt19937 rng(seed);
    const CostGrid grid = randomGrid(rng, 1 + static_cast<int>(rng() % 45), 1 + static_cast<int>(rng() % 45));
    for (int k = 0; k < 4; ++k) {
      GridSearchRequest request;
      request.source = randomCell(rng, grid);
      request.window = randomWindow(rng, grid);
      request.reverse_costs = rng() % 2 == 0;
      request.keep_moves = true;
      const std::vector<double> reference = referenceCosts(grid, *request.window, request.source, request.reverse_costs);

      const GridSearchResult field = eaci::searchGrid(grid, request);
      workspace.search(grid, request);
      double largest = 0.0;
      for (std::size_t i = 0; i < grid.cellCount(); ++i) {
        const Cell c = grid.cellAt(i);
        if (std::isinf(reference[i])) {
          EXPECT_TRUE(std::isinf(field.at(c))) << "seed " << seed;
          EXPECT_TRUE(std::isinf(workspace.at(c))) << "seed " << seed;
          continue;
        }
        largest = std::max(largest, reference[i]);
        EXPECT_NEAR(field.at(c), reference[i], tolerance(reference[i])) << "seed " << seed;
        EXPECT_EQ(workspace.at(c), field.at(c)) << "seed " << seed;  // the same search, to the bit
        if (!request.reverse_costs) {  // the kept moves lead back along a route of that cost
          const eaci::CellPath route = field.routeTo(c);
          EXPECT_EQ(eaci::test::routeDefect(grid, route, request.source, c), "") << "seed " << seed;
          EXPECT_NEAR(eaci::routeCost(grid, route), reference[i], tolerance(reference[i])) << "seed " << seed;
          EXPECT_EQ(workspace.routeTo(c), route) << "seed " << seed;
        }
      }
      EXPECT_NEAR(field.largest_distance, largest, tolerance(largest)) << "seed " << seed;
      EXPECT_EQ(workspace.largestDistance(), field.largest_distance) << "seed " << seed;

      // A* towards a target: the target's cost, and a route of that cost.
      const Cell target = randomCell(rng, grid);
      request.target = target;
      const GridSearchResult astar = eaci::searchGrid(grid, request);
      workspace.search(grid, request);
      const double expected = reference[grid.index(target)];
      if (!request.window->contains(target) || std::isinf(expected)) {
        EXPECT_FALSE(astar.reached(target)) << "seed " << seed;
        EXPECT_FALSE(workspace.reached(target)) << "seed " << seed;
        continue;
      }
      ++compared_routes;
      EXPECT_NEAR(astar.at(target), expected, tolerance(expected)) << "seed " << seed;
      EXPECT_EQ(workspace.at(target), astar.at(target)) << "seed " << seed;
      if (!request.reverse_costs) {
        EXPECT_NEAR(eaci::routeCost(grid, workspace.routeTo(target)), expected, tolerance(expected)) << "seed " << seed;
        EXPECT_EQ(workspace.routeTo(target), astar.routeTo(target)) << "seed " << seed;
      }
    }
  }
  EXPECT_GT(compared_routes, 60);
}

TEST(GridSearch, ShortestPathIsTheSameWithOrWithoutAWorkspace) {
  GridSearchWorkspace workspace;
  int found = 0;
  for (std::uint32_t seed = 100; seed < 140; ++seed) {
    std::mt19937 rng(seed);
    const CostGrid grid = randomGrid(rng, 2 + static_cast<int>(rng() % 60), 2 + static_cast<int>(rng() % 60));
    for (int k = 0; k < 5; ++k) {
      const Cell start = randomCell(rng, grid), goal = randomCell(rng, grid);
      const eaci::ShortestPath fresh = eaci::shortestPath(grid, start, goal);
      const eaci::ShortestPath reused = eaci::shortestPath(grid, start, goal, workspace);
      ASSERT_EQ(reused.found, fresh.found) << "seed " << seed;
      EXPECT_EQ(reused.path, fresh.path) << "seed " << seed;
      if (!fresh.found) continue;
      ++found;
      EXPECT_EQ(reused.cost, fresh.cost) << "seed " << seed;
      const std::vector<double> reference = referenceCosts(grid, CellWindow::whole(grid), start, false);
      EXPECT_NEAR(fresh.cost, reference[grid.index(goal)], tolerance(fresh.cost)) << "seed " << seed;
    }
  }
  EXPECT_GT(found, 50);
}

TEST(GridSearch, FloodReachesWhatDijkstraReaches) {
  GridSearchWorkspace workspace;
  for (std::uint32_t seed = 200; seed < 230; ++seed) {
    std::mt19937 rng(seed);
    const CostGrid grid = randomGrid(rng, 1 + static_cast<int>(rng() % 50), 1 + static_cast<int>(rng() % 50));
    GridSearchRequest request;
    request.source = randomCell(rng, grid);
    request.window = randomWindow(rng, grid);
    request.order = eaci::SearchOrder::kAnyOrder;
    const std::vector<double> reference = referenceCosts(grid, *request.window, request.source, false);
    const GridSearchResult flood = eaci::searchGrid(grid, request);
    workspace.search(grid, request);
    for (std::size_t i = 0; i < grid.cellCount(); ++i) {
      const Cell c = grid.cellAt(i);
      EXPECT_EQ(flood.reached(c), std::isfinite(reference[i])) << "seed " << seed;
      EXPECT_EQ(workspace.reached(c), std::isfinite(reference[i])) << "seed " << seed;
    }
  }
}

// A window that runs past the grid's edge: the search stays on the grid.
TEST(GridSearch, WindowPastTheGridEdgeStaysOnTheGrid) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0}, {0, 1, 0}, {0, 0, 0}}, false);
  GridSearchRequest request;
  request.source = Cell{0, 0};
  request.window = CellWindow{0, 0, 5, 5};
  const GridSearchResult field = eaci::searchGrid(grid, request);
  EXPECT_DOUBLE_EQ(field.at(Cell{2, 2}), 4.0);  // round the centre, no corner cutting
  EXPECT_TRUE(std::isinf(field.at(Cell{1, 1})));
  EXPECT_TRUE(std::isinf(field.at(Cell{3, 3})));
  GridSearchWorkspace workspace;
  workspace.search(grid, request);
  EXPECT_DOUBLE_EQ(workspace.at(Cell{2, 2}), 4.0);
  EXPECT_TRUE(std::isinf(workspace.at(Cell{3, 3})));
}

// The workspace numbers its searches in 16 bits: when the numbers wrap round, the labels of the
// search 65 536 searches back must not come back.
TEST(GridSearch, WorkspaceForgetsOldLabelsWhenItsSearchNumbersWrap) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 1}}, false);
  GridSearchWorkspace workspace;
  GridSearchRequest request;
  request.source = Cell{0, 0};
  workspace.search(grid, request);
  ASSERT_TRUE(workspace.reached(Cell{0, 1}));
  request.source = Cell{0, 2};  // blocked: reaches nothing
  for (int k = 0; k < 65535; ++k) workspace.search(grid, request);
  EXPECT_FALSE(workspace.reached(Cell{0, 1}));
  EXPECT_FALSE(workspace.reached(Cell{0, 0}));
  request.source = Cell{0, 1};
  workspace.search(grid, request);
  EXPECT_DOUBLE_EQ(workspace.at(Cell{0, 0}), 1.0);
}

// The search that meets in the middle (geodesic islands' route on large maps): the cost of the
// independent Dijkstra, a route of allowed moves that costs that much, and the same route on
// one thread and on two. Maps up to 45 x 45 take one round; the 200 x 200 ones many.
TEST(GridSearch, RouteThatMeetsInTheMiddleCostsWhatAnIndependentDijkstraSays) {
  GridSearchWorkspace one_thread, two_threads;
  int routes = 0;
  for (std::uint32_t seed = 1; seed <= 70; ++seed) {
    std::mt19937 rng(seed);
    const int side = seed <= 64 ? 1 + static_cast<int>(rng() % 45) : 200;
    const CostGrid grid = randomGrid(rng, side, 1 + static_cast<int>(rng() % static_cast<unsigned>(side)));
    for (int k = 0; k < 3; ++k) {
      const Cell source = randomCell(rng, grid);
      const Cell target = k == 2 ? source : randomCell(rng, grid);
      SCOPED_TRACE("seed " + std::to_string(seed) + ", request " + std::to_string(k));
      const double expected = grid.isFree(target) ? referenceCosts(grid, CellWindow::whole(grid), source, false)[grid.index(target)] : kInf;
      double cost = 0.0, cost_two = 0.0;
      const eaci::CellPath route = one_thread.cheapestRouteBetween(grid, source, target, 1, &cost);
      const eaci::CellPath route_two = two_threads.cheapestRouteBetween(grid, source, target, 2, &cost_two);
      EXPECT_EQ(route, route_two);
      EXPECT_EQ(cost, cost_two);
      if (std::isinf(expected)) {
        EXPECT_TRUE(route.empty());
        EXPECT_TRUE(std::isinf(cost));
        continue;
      }
      ++routes;
      EXPECT_NEAR(cost, expected, tolerance(expected));
      EXPECT_EQ(eaci::test::routeDefect(grid, route, source, target), "");
      EXPECT_NEAR(eaci::routeCost(grid, route), expected, tolerance(expected));
    }
  }
  EXPECT_GT(routes, 100);
}

// Its labels from the target share the workspace's 16-bit search numbers: after a wrap no old
// label may join a route.
TEST(GridSearch, RouteThatMeetsInTheMiddleForgetsOldLabelsWhenTheNumbersWrap) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0, 1, 0}}, false);
  GridSearchWorkspace workspace;
  ASSERT_EQ(workspace.cheapestRouteBetween(grid, Cell{0, 0}, Cell{0, 2}).size(), 3u);
  GridSearchRequest request;
  request.source = Cell{0, 3};  // blocked: reaches nothing
  for (int k = 0; k < 65535; ++k) workspace.search(grid, request);
  double cost = 0.0;
  EXPECT_TRUE(workspace.cheapestRouteBetween(grid, Cell{0, 4}, Cell{0, 0}, 1, &cost).empty());
  EXPECT_TRUE(std::isinf(cost));
  EXPECT_EQ(workspace.cheapestRouteBetween(grid, Cell{0, 2}, Cell{0, 0}, 1, &cost).size(), 3u);
  EXPECT_DOUBLE_EQ(cost, 2.0);
}

// The meeting search's open list: buckets of width 1/4 in order, first in first out within a
// bucket, stale entries dropped, a priority beyond the ring (64 priority units) kept aside
// until the ring reaches it, and the lower bound of a bucket its lower edge.
TEST(GridSearch, BucketQueueLeavesByBucketThenByArrival) {
  eaci::detail::BucketQueue queue;
  std::vector<bool> stale(8, false);
  const auto is_stale = [&](const eaci::detail::BucketEntry& e) { return stale[e.slot]; };
  queue.push(5.1, {5.1, 0});    // bucket 20
  queue.push(0.3, {0.3, 1});    // bucket 1
  queue.push(300.0, {300.0, 2});  // bucket 1200: beyond the ring of 256 buckets
  queue.push(0.26, {0.26, 3});  // bucket 1, after slot 1
  queue.push(0.1, {0.1, 4});    // bucket 0
  queue.push(5.2, {5.2, 5});    // bucket 20, stale by the time it would leave
  stale[5] = true;
  double bound = -1.0;
  ASSERT_TRUE(queue.lowerBound(bound, is_stale));
  EXPECT_EQ(bound, 0.0);
  std::vector<std::uint32_t> order;
  eaci::detail::BucketEntry e{};
  while (queue.pop(e, is_stale)) {
    order.push_back(e.slot);
    if (e.slot == 3) {  // bucket 1 is open: a push below it joins it, one into it comes last in it
      queue.push(0.0, {0.0, 6});
      ASSERT_TRUE(queue.lowerBound(bound, is_stale));
      EXPECT_EQ(bound, 0.25);
    }
  }
  EXPECT_EQ(order, std::vector<std::uint32_t>({4, 1, 3, 6, 0, 2}));
  EXPECT_FALSE(queue.lowerBound(bound, is_stale));
  queue.clear();
  queue.push(1.0, {1.0, 7});
  ASSERT_TRUE(queue.pop(e, is_stale));
  EXPECT_EQ(e.slot, 7u);
}
