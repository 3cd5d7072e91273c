// The grid search (searchGrid and GridSearchWorkspace) against the suite's reference Dijkstra
// (test_support.hpp: the move rule written out, not CostGrid's canMove / moveCost), on random
// cost maps with several cost rules (one steep enough to spread priorities far apart), corner
// rules, windows, targets and reversed costs; one workspace serves maps of every size in turn.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <future>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <queue>
#include <random>
#include <string>
#include <system_error>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "eaci/search/astar.hpp"
#include "eaci/search/landmark_cache.hpp"
#include "eaci/search/landmarks.hpp"
#include "eaci/search/meeting_search.hpp"
#include "blocking_landmark_maker.hpp"
#include "eaci/planner.hpp"
#include "test_support.hpp"

using eaci::Cell;
using eaci::CellWindow;
using eaci::CostGrid;
using eaci::GridSearchRequest;
using eaci::GridSearchResult;
using eaci::GridSearchWorkspace;
using eaci::MeetingSearch;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Route costs from `source` to every cell of the window (reverse: from every cell to `source`),
// by grid index; routes stay inside the window. The suite's reference Dijkstra (test_support.hpp).
std::vector<double> referenceCosts(const CostGrid& grid, const CellWindow& window, Cell source, bool reverse) {
  const auto inside = [window](int r, int c) { return window.contains(Cell{r, c}); };
  return eaci::test::referenceCosts(eaci::test::referenceGridOf(grid, inside), source, reverse);
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

TEST(GridSearch, CostsEqualAnIndependentDijkstraOnRandomCostMaps) {
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
      EXPECT_NEAR(field.largest_cost, largest, tolerance(largest)) << "seed " << seed;

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

TEST(GridSearch, CheapestPathIsTheSameWithOrWithoutAWorkspace) {
  GridSearchWorkspace workspace;
  int found = 0;
  for (std::uint32_t seed = 100; seed < 140; ++seed) {
    std::mt19937 rng(seed);
    const CostGrid grid = randomGrid(rng, 2 + static_cast<int>(rng() % 60), 2 + static_cast<int>(rng() % 60));
    for (int k = 0; k < 5; ++k) {
      const Cell start = randomCell(rng, grid), goal = randomCell(rng, grid);
      const eaci::CheapestPath fresh = eaci::cheapestPath(grid, start, goal);
      const eaci::CheapestPath reused = eaci::cheapestPath(grid, start, goal, workspace);
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

// The workspace numbers its searches in 12 bits: when the numbers wrap round, the labels of the
// search 4095 searches back, which had the number the search now has, must not come back.
TEST(GridSearch, WorkspaceForgetsOldLabelsWhenItsSearchNumbersWrap) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 1}}, false);
  GridSearchWorkspace workspace;
  GridSearchRequest request;
  request.source = Cell{0, 0};
  workspace.search(grid, request);
  ASSERT_TRUE(workspace.reached(Cell{0, 1}));
  request.source = Cell{0, 2};  // blocked: reaches nothing
  for (int k = 0; k < eaci::detail::kMaxGeneration; ++k) workspace.search(grid, request);
  EXPECT_FALSE(workspace.reached(Cell{0, 1}));
  EXPECT_FALSE(workspace.reached(Cell{0, 0}));
  request.source = Cell{0, 1};
  workspace.search(grid, request);
  EXPECT_DOUBLE_EQ(workspace.at(Cell{0, 0}), 1.0);
}

namespace {

// The most a route of `moves` moves found on float labels may cost above the cheapest, `cheapest`:
// each move rounds a label by at most 2^-24 of it, on the route found and on the cheapest.
double floatLabelSlack(double cheapest, std::size_t moves) {
  return cheapest * 2.0 * static_cast<double>(moves) * std::ldexp(1.0, -24) + tolerance(cheapest);
}

// Asks both searches (one thread, two) for the route that meets in the middle and checks it
// against the independent Dijkstra: the same route and cost from both, a route of allowed
// moves that costs the Dijkstra's cost up to the labels' float rounding (floatLabelSlack).
// Returns whether a route exists.
bool expectMeetingRouteAsDijkstraSays(const CostGrid& grid, Cell source, Cell target, MeetingSearch& one_thread,
                                      MeetingSearch& two_threads) {
  const double expected =
      grid.isFree(target) ? referenceCosts(grid, CellWindow::whole(grid), source, false)[grid.index(target)] : kInf;
  double cost = 0.0, cost_two = 0.0;
  const eaci::CellPath route = one_thread.cheapestRoute(grid, source, target, 1, &cost);
  const eaci::CellPath route_two = two_threads.cheapestRoute(grid, source, target, 2, &cost_two);
  EXPECT_EQ(route, route_two);
  EXPECT_EQ(cost, cost_two);
  if (std::isinf(expected)) {
    EXPECT_TRUE(route.empty());
    EXPECT_TRUE(std::isinf(cost));
    return false;
  }
  EXPECT_EQ(eaci::test::routeDefect(grid, route, source, target), "");
  EXPECT_EQ(cost, eaci::routeCost(grid, route));  // summed exactly along the route
  EXPECT_GE(cost, expected - tolerance(expected));
  EXPECT_LE(cost, expected + floatLabelSlack(expected, route.size()));
  return true;
}

}  // namespace

// The search that meets in the middle (geodesic islands' route on large maps): the cost of the
// independent Dijkstra, a route of allowed moves that costs that much, and the same route on
// one thread and on two. Maps up to 45 x 45 take one round; the 200 x 200 ones many.
TEST(GridSearch, RouteThatMeetsInTheMiddleCostsWhatAnIndependentDijkstraSays) {
  MeetingSearch one_thread, two_threads;
  int routes = 0;
  for (std::uint32_t seed = 1; seed <= 70; ++seed) {
    std::mt19937 rng(seed);
    const int side = seed <= 64 ? 1 + static_cast<int>(rng() % 45) : 200;
    const CostGrid grid = randomGrid(rng, side, 1 + static_cast<int>(rng() % static_cast<unsigned>(side)));
    for (int k = 0; k < 3; ++k) {
      const Cell source = randomCell(rng, grid);
      const Cell target = k == 2 ? source : randomCell(rng, grid);
      SCOPED_TRACE("seed " + std::to_string(seed) + ", request " + std::to_string(k));
      if (expectMeetingRouteAsDijkstraSays(grid, source, target, one_thread, two_threads)) ++routes;
    }
  }
  EXPECT_GT(routes, 100);
}

// Its two sides' labels share one count of 12-bit search numbers: after a wrap no old label
// may join a route.
TEST(GridSearch, RouteThatMeetsInTheMiddleForgetsOldLabelsWhenTheNumbersWrap) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0, 1, 0}}, false);
  MeetingSearch search;
  ASSERT_EQ(search.cheapestRoute(grid, Cell{0, 0}, Cell{0, 2}).size(), 3u);
  for (int k = 0; k < eaci::detail::kMaxGeneration; ++k)
    search.cheapestRoute(grid, Cell{0, 3}, Cell{0, 0});  // blocked: reaches nothing
  double cost = 0.0;
  EXPECT_TRUE(search.cheapestRoute(grid, Cell{0, 4}, Cell{0, 0}, 1, &cost).empty());
  EXPECT_TRUE(std::isinf(cost));
  EXPECT_EQ(search.cheapestRoute(grid, Cell{0, 2}, Cell{0, 0}, 1, &cost).size(), 3u);
  EXPECT_DOUBLE_EQ(cost, 2.0);
}

// The meeting search's open list: buckets of width 1/4 in order, first in first out within a
// bucket, stale entries dropped, a priority beyond the ring (64 priority units) kept aside
// until the ring reaches it, and the lower bound of a bucket its lower edge.
TEST(GridSearch, BucketQueueLeavesByBucketThenByArrival) {
  eaci::detail::BucketQueue<> queue;
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

// Landmark bounds (ALT) against the independent Dijkstra: never above a route's cost either
// way, consistent along every allowed move (so the meeting search may use them), on random
// cost maps with every cost rule above, obstacles that split the map, and both corner rules.
TEST(Landmarks, BoundsNeverExceedRouteCostsAndChangeByNoMoreThanAMoveCosts) {
  int pairs = 0;
  for (std::uint32_t seed = 1; seed <= 24; ++seed) {
    std::mt19937 rng(seed);
    const CostGrid grid = randomGrid(rng, 5 + static_cast<int>(rng() % 40), 5 + static_cast<int>(rng() % 40));
    const auto landmarks = eaci::Landmarks::compute(grid, 1 + static_cast<int>(rng() % 6));
    if (!landmarks) continue;  // no free cell
    SCOPED_TRACE("seed " + std::to_string(seed));
    for (int k = 0; k < 4; ++k) {
      const Cell target = randomCell(rng, grid);
      if (!grid.isFree(target)) continue;
      const std::vector<double> to_target = referenceCosts(grid, CellWindow::whole(grid), target, true);
      const std::vector<double> from_target = referenceCosts(grid, CellWindow::whole(grid), target, false);
      const std::size_t t = grid.index(target);
      for (std::size_t i = 0; i < grid.cellCount(); ++i) {
        const Cell here = grid.cellAt(i);
        if (!grid.isFree(here)) continue;
        const double bound = landmarks->lowerBound(landmarks->of(i), landmarks->of(t));
        ++pairs;
        EXPECT_LE(bound, to_target[i] + tolerance(to_target[i]));
        EXPECT_LE(bound, from_target[i] + tolerance(from_target[i]));
        for (int d = 0; d < eaci::kDirections; ++d) {
          if (!grid.canMove(here, d)) continue;
          const std::size_t j = grid.index(eaci::step(here, d));
          EXPECT_LE(bound - landmarks->lowerBound(landmarks->of(j), landmarks->of(t)), grid.moveCost(here, d)) << "move " << d << " from cell " << i;
        }
      }
    }
  }
  EXPECT_GT(pairs, 2000);
}

// A 6 x 6 map split by a wall with one door at its foot: a landmark left of the wall bounds a
// route across it by the detour through the door, not by the straight line.
TEST(Landmarks, BoundAcrossAWallCountsTheDetour) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 1, 0, 0, 0},
                                            {0, 0, 1, 0, 0, 0},
                                            {0, 0, 1, 0, 0, 0},
                                            {0, 0, 1, 0, 0, 0},
                                            {0, 0, 1, 0, 0, 0},
                                            {0, 0, 0, 0, 0, 0}},
                                           false);
  const auto landmarks = eaci::Landmarks::compute(grid, 2);
  ASSERT_TRUE(landmarks);
  // (0,1) to (0,3): octile 2; the route goes down 5 cells, 2 along the foot of the wall (no
  // corner cutting past its end) and up 5: 12.
  const double bound =
      landmarks->lowerBound(landmarks->of(grid.index(Cell{0, 1})), landmarks->of(grid.index(Cell{0, 3})));
  EXPECT_GT(bound, 3 * 2.0);
  EXPECT_LE(bound, 12.0);
}

TEST(Landmarks, HoldOnCostlierGridsNotOnCheaperOnes) {
  CostGrid grid(20, 10, false);
  grid.setCost(Cell{4, 4}, 100);
  grid.setBlocked(Cell{5, 5}, true);
  const auto landmarks = eaci::Landmarks::compute(grid, 3);
  ASSERT_TRUE(landmarks);
  EXPECT_TRUE(landmarks->holdsFor(grid));
  CostGrid costlier = grid;
  costlier.setCost(Cell{1, 1}, 200);
  costlier.setBlocked(Cell{4, 4}, true);
  EXPECT_TRUE(landmarks->holdsFor(costlier));
  CostGrid cheaper = grid;
  cheaper.setCost(Cell{4, 4}, 99);
  EXPECT_FALSE(landmarks->holdsFor(cheaper));
  CostGrid cleared = grid;
  cleared.setBlocked(Cell{5, 5}, false);
  EXPECT_FALSE(landmarks->holdsFor(cleared));
  CostGrid other_rule = grid;
  other_rule.setCostRule({50.0, 1.0});
  EXPECT_FALSE(landmarks->holdsFor(other_rule));
  EXPECT_FALSE(landmarks->holdsFor(CostGrid(20, 11, false)));
  EXPECT_FALSE(landmarks->holdsFor(CostGrid(20, 10, true)));
}

namespace {

// Landmarks from `cache` that hold on `grid`, asked for as a plan asks (usableFor) until the
// background thread has made them; null after two minutes.
std::shared_ptr<const eaci::Landmarks> landmarksOnceMade(eaci::LandmarkCache& cache, const CostGrid& grid) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  for (;;) {
    if (auto made = cache.usableFor(grid)) return made;
    if (std::chrono::steady_clock::now() > deadline) return nullptr;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

// Starts a cache's threads (LandmarkCache's ThreadStarter) and counts the ones that finished,
// so that a test can wait for the landmarks under way, made or failed. The cache detaches its
// threads: the count lives in a state each thread owns a share of.
class FinishedThreads {
 public:
  // `hold`: the threads start their bodies only once release() is called.
  explicit FinishedThreads(bool hold = false) { state_->held = hold; }
  eaci::ThreadStarter starter() {
    return [state = state_](std::function<void()> body) {
      return std::thread([state, body = std::move(body)]() mutable {
        {
          std::unique_lock<std::mutex> lock(state->mutex);
          state->changed.wait(lock, [&] { return !state->held; });
        }
        body();
        body = nullptr;  // what the job owns goes before it counts as finished
        std::lock_guard<std::mutex> lock(state->mutex);
        ++state->finished;
        state->changed.notify_all();
      });
    };
  }
  void release() {
    std::lock_guard<std::mutex> lock(state_->mutex);
    state_->held = false;
    state_->changed.notify_all();
  }
  // Waits (two minutes at most) until `count` threads have finished; false if they did not.
  bool waitFor(int count) {
    std::unique_lock<std::mutex> lock(state_->mutex);
    return state_->changed.wait_for(lock, std::chrono::minutes(2), [&] { return state_->finished >= count; });
  }

 private:
  struct State {
    std::mutex mutex;
    std::condition_variable changed;
    bool held = false;
    int finished = 0;
  };
  std::shared_ptr<State> state_ = std::make_shared<State>();
};

}  // namespace

// Kept in a cache: none at first (made in the background), then the same ones for a costlier
// costmap, and new ones, holding for both, after a cell got cheaper.
TEST(Landmarks, CacheMakesThemInTheBackgroundAndAgainWhenTheMapGetsCheaper) {
  CostGrid grid(30, 30, false);
  for (int r = 3; r < 27; ++r) grid.setCost(Cell{r, 15}, 200);
  FinishedThreads threads;
  eaci::LandmarkCache cache(2, {}, threads.starter());
  EXPECT_EQ(cache.usableFor(grid), nullptr);
  ASSERT_TRUE(threads.waitFor(1));
  const auto made = cache.usableFor(grid);
  ASSERT_NE(made, nullptr);
  EXPECT_EQ(made->count(), 2);
  CostGrid costlier = grid;
  costlier.setBlocked(Cell{0, 0}, true);
  EXPECT_EQ(cache.usableFor(costlier), made);
  CostGrid cheaper = grid;
  cheaper.setCost(Cell{10, 15}, 0);
  cheaper.setBlocked(Cell{29, 29}, true);
  EXPECT_EQ(cache.usableFor(cheaper), nullptr);
  ASSERT_TRUE(threads.waitFor(2));
  const auto remade = cache.usableFor(cheaper);
  ASSERT_NE(remade, nullptr);
  EXPECT_NE(remade, made);
  EXPECT_TRUE(remade->holdsFor(grid));
  EXPECT_TRUE(remade->holdsFor(cheaper));
}

// A grid kept from plan to plan and changed in place (the planning service's CostmapMirror) is
// checked again only where it changed (CostGrid::rowChange): after every change the cache's
// answer agrees with the full check (Landmarks::holdsFor) -- a cell made cheaper anywhere, an
// obstacle cleared, and the same cell set back.
TEST(Landmarks, CacheChecksAKeptGridAgainWhereItChanged) {
  CostGrid grid(40, 30, false);
  for (int r = 3; r < 27; ++r) grid.setCost(Cell{r, 20}, 150);
  for (int c = 5; c < 15; ++c) grid.setBlocked(Cell{10, c}, true);
  int started = 0;  // the first job makes them; later ones never run (the landmarks stay these)
  eaci::ThreadStarter first_only = [&started](std::function<void()> body) {
    return started++ == 0 ? std::thread(std::move(body)) : std::thread([] {});
  };
  eaci::LandmarkCache cache(2, {}, first_only);
  const auto made = landmarksOnceMade(cache, grid);
  ASSERT_NE(made, nullptr);
  const CostGrid original = grid;

  grid.setCost(Cell{20, 20}, 200);  // costlier: they hold
  EXPECT_EQ(cache.usableFor(grid), made);
  grid.setCost(Cell{29, 39}, 0);    // as it was (0): they hold
  EXPECT_EQ(cache.usableFor(grid), made);
  grid.setCost(Cell{25, 20}, 149);  // cheaper, far from the last change: they do not
  EXPECT_EQ(cache.usableFor(grid), nullptr);
  grid.setCost(Cell{25, 20}, 150);  // back: they hold again
  EXPECT_EQ(cache.usableFor(grid), made);
  grid.setBlocked(Cell{10, 7}, false);  // an obstacle cleared: they do not
  EXPECT_EQ(cache.usableFor(grid), nullptr);
  grid.setBlocked(Cell{10, 7}, true);
  EXPECT_EQ(cache.usableFor(grid), made);

  std::mt19937 random(11);
  std::uniform_int_distribution<int> row(0, 29), col(0, 39), cost(0, 254);
  for (int step = 0; step < 400; ++step) {
    const Cell cell{row(random), col(random)};
    const int value = cost(random);
    if (value == 254) grid.setBlocked(cell, true);
    else if (value > 230) grid.setCost(cell, original.isBlocked(cell) ? 0 : original.cost(cell));  // often back
    else grid.setCost(cell, static_cast<std::uint8_t>(value));
    ASSERT_EQ(cache.usableFor(grid) == made, made->holdsFor(grid)) << "step " << step;
  }
}

// A cache destroyed while it makes landmarks on a large map returns at once (it waits for no
// thread) and its landmark thread stops instead of finishing: the maker (Landmarks::compute,
// wrapped to see its answer) returns none. The destruction runs on a thread of its own so that
// a hang fails here instead of at the suite's timeout; the stop is waited for with a bound that
// only guards against a hang (the thread runs at nice 19: on a loaded machine it may take
// seconds to be scheduled and see the flag).
TEST(Landmarks, CacheDestroyedWhileMakingThemStops) {
  constexpr auto kHangBound = std::chrono::seconds(60);
  const CostGrid grid(2000, 2000, false);
  struct Seen {
    std::mutex mutex;
    std::condition_variable changed;
    bool called = false;
    int made = 0;  // 1: stopped with none, 2: finished
  };
  auto seen = std::make_shared<Seen>();
  auto cache = std::make_unique<eaci::LandmarkCache>(8, [seen](const CostGrid& g, int count, const std::atomic<bool>* cancel) {
    {
      std::lock_guard<std::mutex> lock(seen->mutex);
      seen->called = true;
      seen->changed.notify_all();
    }
    auto landmarks = eaci::Landmarks::compute(g, count, cancel);
    std::lock_guard<std::mutex> lock(seen->mutex);
    seen->made = landmarks ? 2 : 1;
    seen->changed.notify_all();
    return landmarks;
  });
  EXPECT_EQ(cache->usableFor(grid), nullptr);
  EXPECT_EQ(cache->jobsStarted(), 1);
  {  // making them has begun (a job cancelled before that never calls the maker)
    std::unique_lock<std::mutex> lock(seen->mutex);
    ASSERT_TRUE(seen->changed.wait_for(lock, kHangBound, [&] { return seen->called; }));
  }
  auto destroyed = std::make_shared<std::promise<void>>();
  std::future<void> done = destroyed->get_future();
  std::thread([cache = std::move(cache), destroyed]() mutable {
    cache.reset();  // cancels the landmark thread and lets it go
    destroyed->set_value();
  }).detach();  // left behind if it hangs: the process ends after the failure
  ASSERT_EQ(done.wait_for(kHangBound), std::future_status::ready) << "destroying the cache did not return within 60 s";
  std::unique_lock<std::mutex> lock(seen->mutex);
  ASSERT_TRUE(seen->changed.wait_for(lock, kHangBound, [&] { return seen->made != 0; }))
      << "the landmark thread did not stop within 60 s";
  EXPECT_EQ(seen->made, 1) << "the landmarks were finished instead of stopped";
}

// Issue #27: no plan waits for the landmark thread. Each test holds the maker blocked
// (eaci_test::LandmarkGate) while the plan-side step runs, then releases it and waits for every
// maker call to return, so that no thread outlives the test.

// (a) A map of another size cancels the job in flight without waiting; the new size, once
// settled (asked on twice in a row, as the old size's table was wasted), gets a job of its own,
// whose landmarks are the ones kept.
TEST(Landmarks, ANewMapSizeReturnsWhileTheMakerIsStillBlocked) {
  auto gate = std::make_shared<eaci_test::LandmarkGate>();
  auto cache = std::make_shared<eaci::LandmarkCache>(2, eaci_test::LandmarkGate::maker(gate));
  const CostGrid grid(64, 64, false), larger(80, 64, false);
  EXPECT_EQ(cache->usableFor(grid), nullptr);
  ASSERT_TRUE(gate->waitEntered(1));
  EXPECT_TRUE(eaci_test::returnsWhileTheMakerIsBlocked(gate, [cache, larger] {
    EXPECT_EQ(cache->usableFor(larger), nullptr);  // not settled yet: nothing started
    EXPECT_EQ(cache->jobsStarted(), 1);
    EXPECT_EQ(cache->usableFor(larger), nullptr);  // settled: a job for it
    EXPECT_EQ(cache->jobsStarted(), 2);
  }));
  ASSERT_TRUE(gate->waitEntered(2));
  gate->release();
  ASSERT_TRUE(gate->waitLeft(2));
  EXPECT_EQ(gate->cancelled(), 1);  // the job for the old size
  const auto made = landmarksOnceMade(*cache, larger);
  ASSERT_NE(made, nullptr);
  EXPECT_TRUE(made->holdsFor(larger));
  EXPECT_EQ(cache->jobsFinished(), 1);
}

// (a') The job is done but its thread has not ended (a nice-19 thread on a loaded machine is
// late to end, and the cache used to join it before starting the next job and in its
// destructor): neither a new job nor the cache's destruction waits for that thread.
TEST(Landmarks, AFinishedJobWhoseThreadHasNotEndedIsNotWaitedFor) {
  auto gate = std::make_shared<eaci_test::LandmarkGate>();
  eaci::ThreadStarter late_to_end = [gate](std::function<void()> body) {
    return std::thread([gate, body = std::move(body)]() mutable {
      body();
      body = nullptr;
      gate->hold();
    });
  };
  const CostGrid grid(64, 64, false), larger(80, 64, false);
  auto cache = std::make_shared<std::unique_ptr<eaci::LandmarkCache>>(
      std::make_unique<eaci::LandmarkCache>(2, eaci::LandmarkCache::Maker{}, late_to_end, 1));
  EXPECT_EQ((*cache)->usableFor(grid), nullptr);
  ASSERT_TRUE(gate->waitEntered(1));  // the job is done; its thread has not ended
  EXPECT_TRUE(eaci_test::returnsWhileTheMakerIsBlocked(gate, [cache, grid, larger] {
    ASSERT_NE((*cache)->usableFor(grid), nullptr);  // the job's landmarks
    EXPECT_EQ((*cache)->usableFor(larger), nullptr);   // a new size: a new job at once (no policy)
    EXPECT_EQ((*cache)->jobsStarted(), 2);
    cache->reset();
  }));
  gate->release();
  ASSERT_TRUE(gate->waitLeft(1));
}

// (b) A change of count (a rolling window: useLandmarks(0), then landmarks again) drops the
// cache whose maker is blocked, and the next search runs (without landmarks) at once.
TEST(Landmarks, AChangeOfCountReturnsWhileTheMakerIsStillBlocked) {
  auto gate = std::make_shared<eaci_test::LandmarkGate>();
  auto search = std::make_shared<MeetingSearch>();
  const CostGrid grid(64, 64, false);
  search->useLandmarks(4, eaci_test::LandmarkGate::maker(gate));
  EXPECT_FALSE(search->cheapestRoute(grid, Cell{1, 1}, Cell{60, 60}).empty());
  ASSERT_TRUE(gate->waitEntered(1));
  EXPECT_TRUE(eaci_test::returnsWhileTheMakerIsBlocked(gate, [search, grid, gate] {
    search->useLandmarks(0);
    EXPECT_EQ(search->landmarkCache(), nullptr);
    EXPECT_FALSE(search->cheapestRoute(grid, Cell{1, 1}, Cell{60, 60}).empty());
    search->useLandmarks(2, eaci_test::LandmarkGate::maker(gate));
    EXPECT_FALSE(search->cheapestRoute(grid, Cell{1, 1}, Cell{60, 60}).empty());  // starts a job, which blocks
    search->useLandmarks(3, eaci_test::LandmarkGate::maker(gate));
    EXPECT_FALSE(search->cheapestRoute(grid, Cell{1, 1}, Cell{60, 60}).empty());
  }));
  // The second cache's job may have been cancelled before it called the maker (then it never
  // does); the last cache's job is not cancelled and makes its landmarks once released.
  gate->release();
  ASSERT_NE(landmarksOnceMade(*search->landmarkCache(), grid), nullptr);
  EXPECT_EQ(search->landmarkCache()->countInUse(), 3);
  EXPECT_EQ(search->landmarkCache()->jobsStarted(), 1);
  // The first cache's job, blocked when its cache was dropped, returns cancelled; released with
  // the others, it may return after the last job's landmarks are made, so it is waited for.
  EXPECT_TRUE(gate->waitCancelled(1));
}

// (c) Destroying a cache, a MeetingSearch or a whole PlannerWorkspace (as the service does after
// a plan that threw) while the maker is blocked waits for none of it.
TEST(Landmarks, DestroyingTheCacheOrItsOwnersReturnsWhileTheMakerIsStillBlocked) {
  auto gate = std::make_shared<eaci_test::LandmarkGate>();
  const CostGrid grid(64, 64, false);
  auto cache = std::make_unique<eaci::LandmarkCache>(2, eaci_test::LandmarkGate::maker(gate));
  EXPECT_EQ(cache->usableFor(grid), nullptr);
  auto search = std::make_unique<MeetingSearch>();
  search->useLandmarks(4, eaci_test::LandmarkGate::maker(gate));
  search->cheapestRoute(grid, Cell{1, 1}, Cell{60, 60}, 2);
  auto workspace = std::make_unique<eaci::PlannerWorkspace>();
  workspace->meeting.useLandmarks(4, eaci_test::LandmarkGate::maker(gate));
  workspace->meeting.cheapestRoute(grid, Cell{1, 1}, Cell{60, 60}, 2);
  ASSERT_TRUE(gate->waitEntered(3));
  auto owners = std::make_shared<std::tuple<std::unique_ptr<eaci::LandmarkCache>, std::unique_ptr<MeetingSearch>,
                                            std::unique_ptr<eaci::PlannerWorkspace>>>(
      std::move(cache), std::move(search), std::move(workspace));
  EXPECT_TRUE(eaci_test::returnsWhileTheMakerIsBlocked(gate, [owners] {
    std::get<0>(*owners).reset();
    std::get<1>(*owners).reset();
    std::get<2>(*owners).reset();
  }));
  gate->release();
  ASSERT_TRUE(gate->waitLeft(3));
  EXPECT_EQ(gate->cancelled(), 3);
}

// The size policy: after w tables wasted in a row (the size changed before any plan was given
// them) a new size starts a table only once asked on min(1 + w, kMaxSettleAsks) times in a row;
// a table a plan was given makes it eager again. With max_settle_asks 1 (no policy) every size
// starts a job, each cancelling the one before.
TEST(Landmarks, TablesForANewSizeStartOnlyOnceTheSizeIsSettled) {
  FinishedThreads threads(true);  // held while the sizes change: no job ends meanwhile
  eaci::LandmarkCache cache(2, {}, threads.starter());
  EXPECT_EQ(eaci::LandmarkCache::kMaxSettleAsks, 4);
  const auto ask = [&](int size) { return cache.usableFor(CostGrid(size, size, false)); };
  EXPECT_EQ(ask(40), nullptr);
  EXPECT_EQ(cache.jobsStarted(), 1);  // nothing wasted yet: at once
  EXPECT_EQ(ask(44), nullptr);        // the first table wasted: two asks from now on
  EXPECT_EQ(ask(48), nullptr);
  EXPECT_EQ(cache.jobsStarted(), 1);
  EXPECT_EQ(ask(48), nullptr);
  EXPECT_EQ(cache.jobsStarted(), 2);
  EXPECT_EQ(ask(52), nullptr);  // the second wasted: three asks
  EXPECT_EQ(ask(52), nullptr);
  EXPECT_EQ(cache.jobsStarted(), 2);
  EXPECT_EQ(ask(52), nullptr);
  EXPECT_EQ(cache.jobsStarted(), 3);
  threads.release();
  ASSERT_TRUE(threads.waitFor(3));
  const CostGrid settled(52, 52, false);
  const auto made = cache.usableFor(settled);  // given to a plan: eager again
  ASSERT_NE(made, nullptr);
  EXPECT_TRUE(made->holdsFor(settled));
  EXPECT_EQ(ask(56), nullptr);
  EXPECT_EQ(cache.jobsStarted(), 4);
  ASSERT_TRUE(threads.waitFor(4));

  FinishedThreads eager_threads(true);
  eaci::LandmarkCache eager(2, {}, eager_threads.starter(), 1);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(eager.usableFor(CostGrid(40 + 4 * k, 40, false)), nullptr);
  EXPECT_EQ(eager.jobsStarted(), 4);
  eager_threads.release();
  ASSERT_TRUE(eager_threads.waitFor(4));
}

// Every loop that makes landmarks asks its cancel flag: a cancelled flag returns none at once.
TEST(Landmarks, ComputeWithItsCancelFlagSetMakesNone) {
  const CostGrid grid(300, 300, false);
  std::atomic<bool> cancel{true};
  EXPECT_EQ(eaci::Landmarks::compute(grid, 4, &cancel), nullptr);
  cancel = false;
  EXPECT_NE(eaci::Landmarks::compute(grid, 4, &cancel), nullptr);
}

TEST(Landmarks, ThoseThatFitInTheCap) {
  // 256 MiB / 4 bytes = 64 Mi landmark-cells.
  EXPECT_EQ(eaci::kMaxLandmarkBytes, std::size_t{268435456});
  EXPECT_EQ(eaci::landmarksThatFit(std::size_t{2048} * 2048, 20), 16);  // 64 Mi / 4 Mi
  EXPECT_EQ(eaci::landmarksThatFit(std::size_t{2048} * 2048, 8), 8);
  EXPECT_EQ(eaci::landmarksThatFit(std::size_t{8192} * 8192, 4), 1);     // 64 Mi / 64 Mi
  EXPECT_EQ(eaci::landmarksThatFit(std::size_t{8193} * 8192, 4), 0);     // not even one
  EXPECT_EQ(eaci::landmarksThatFit(300 * 300, 1000), 745);               // 67108864 / 90000
  EXPECT_EQ(eaci::landmarksThatFit(300 * 300, 0), 0);
}

// A cache that makes its landmarks with `make` (counting its calls and the count asked for).
struct MakerProbe {
  std::atomic<int> calls{0};
  std::atomic<int> last_count{0};
};

TEST(Landmarks, CacheAsksForNoMoreThanFitAndSaysHowMany) {
  const CostGrid grid(300, 300, false);
  MakerProbe probe;
  FinishedThreads threads;
  eaci::LandmarkCache cache(
      1000,
      [&](const CostGrid& g, int count, const std::atomic<bool>* cancel) {
        probe.calls.fetch_add(1);
        probe.last_count.store(count);
        return eaci::Landmarks::compute(g, 2, cancel);  // two suffice to see them used
      },
      threads.starter());
  EXPECT_EQ(cache.count(), 1000);
  EXPECT_EQ(cache.usableFor(grid), nullptr);
  EXPECT_EQ(cache.countInUse(), 745);  // 67108864 / 90000, as ThoseThatFitInTheCap
  ASSERT_TRUE(threads.waitFor(1));
  EXPECT_EQ(probe.last_count.load(), 745);
  EXPECT_NE(cache.usableFor(grid), nullptr);
  EXPECT_EQ(cache.lastError(), "");
  // On a map where not one fits (8193 x 8192 cells, 67 MB of cell bytes) none are asked for.
  const CostGrid too_big(8193, 8192, false);
  EXPECT_EQ(cache.usableFor(too_big), nullptr);
  EXPECT_EQ(cache.countInUse(), 0);
  EXPECT_EQ(probe.calls.load(), 1);  // no thread was started for it
}

TEST(Landmarks, FailureWhileMakingThemLeavesTheCacheWithoutThemAndTheNextPlanTriesAgain) {
  const CostGrid grid(64, 64, false);
  MakerProbe probe;
  FinishedThreads threads;
  eaci::LandmarkCache cache(
      4,
      [&](const CostGrid& g, int count, const std::atomic<bool>* cancel) {
        if (probe.calls.fetch_add(1) == 0) throw std::bad_alloc();  // the first attempt runs out of memory
        return eaci::Landmarks::compute(g, count, cancel);
      },
      threads.starter());
  EXPECT_EQ(cache.usableFor(grid), nullptr);  // starts the thread, which throws: no std::terminate
  ASSERT_TRUE(threads.waitFor(1));
  EXPECT_NE(cache.lastError().find("bad_alloc"), std::string::npos) << cache.lastError();
  EXPECT_EQ(cache.usableFor(grid), nullptr);  // tries again
  ASSERT_TRUE(threads.waitFor(2));
  EXPECT_EQ(probe.calls.load(), 2);
  EXPECT_EQ(cache.lastError(), "");
  const auto made = cache.usableFor(grid);
  ASSERT_NE(made, nullptr);
  EXPECT_EQ(made->count(), 4);
}

TEST(Landmarks, ThreadThatCannotStartLeavesTheCacheUsableAndTheSearchGoesOnWithoutThem) {
  const CostGrid grid(64, 64, false);
  std::atomic<int> starts{0};
  FinishedThreads threads;
  eaci::LandmarkCache cache(4, {}, [&, start = threads.starter()](std::function<void()> body) {
    if (starts.fetch_add(1) == 0)
      throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again), "no thread");
    return start(std::move(body));
  });
  EXPECT_EQ(cache.usableFor(grid), nullptr);  // no exception out of it
  EXPECT_NE(cache.lastError().find("could not start"), std::string::npos) << cache.lastError();
  EXPECT_EQ(cache.usableFor(grid), nullptr);  // not stuck "under way": starts the thread now
  ASSERT_TRUE(threads.waitFor(1));
  EXPECT_NE(cache.usableFor(grid), nullptr);
  EXPECT_EQ(starts.load(), 2);
}

// With landmarks the search that meets in the middle still costs what the independent Dijkstra
// says, on one thread and on two, over maps large enough to take many rounds.
TEST(Landmarks, RouteThatMeetsInTheMiddleWithLandmarksCostsWhatAnIndependentDijkstraSays) {
  int routes = 0;
  for (std::uint32_t seed = 1; seed <= 8; ++seed) {
    std::mt19937 rng(seed);
    const CostGrid grid = randomGrid(rng, 60 + static_cast<int>(rng() % 140), 60 + static_cast<int>(rng() % 140));
    MeetingSearch one_thread, two_threads;
    one_thread.useLandmarks(4);
    two_threads.useLandmarks(4);
    one_thread.cheapestRoute(grid, Cell{0, 0}, Cell{0, 0});  // a free or blocked corner: starts them or not
    for (int k = 0; k < 12; ++k) {
      const Cell source = randomCell(rng, grid), target = randomCell(rng, grid);
      if (!grid.isFree(source) || !grid.isFree(target)) continue;
      for (MeetingSearch* search : {&one_thread, &two_threads})  // their landmarks made before the search
        ASSERT_NE(landmarksOnceMade(*search->landmarkCache(), grid), nullptr);
      SCOPED_TRACE("seed " + std::to_string(seed) + ", request " + std::to_string(k));
      if (expectMeetingRouteAsDijkstraSays(grid, source, target, one_thread, two_threads)) ++routes;
    }
  }
  EXPECT_GT(routes, 40);
}

// A route in a part of the map the landmarks do not reach (they are chosen in the part of the
// free cell in the middle): their bounds say nothing there, and the search falls back on the
// octile distance, taking exactly the cells the search without landmarks takes.
TEST(Landmarks, ARouteWhereNoLandmarkReachesSearchesByTheOctileBound) {
  CostGrid grid(100, 100, false);
  for (int r = 0; r < 100; ++r) grid.setBlocked(Cell{r, 80}, true);  // columns 81-99: a part of their own
  MeetingSearch plain, with_landmarks;
  with_landmarks.useLandmarks(4);
  const auto made = landmarksOnceMade(*with_landmarks.landmarkCache(), grid);
  ASSERT_NE(made, nullptr);
  ASSERT_TRUE(made->reaches(made->of(grid.index(Cell{50, 40}))));
  ASSERT_FALSE(made->reaches(made->of(grid.index(Cell{5, 85}))));
  const Cell source{5, 85}, target{95, 95};
  double cost = 0.0, cost_with = 0.0;
  const std::size_t moves = plain.cheapestRoute(grid, source, target, 1, &cost).size();
  with_landmarks.cheapestRoute(grid, source, target, 1, &cost_with);
  EXPECT_FALSE(with_landmarks.usedLandmarks());
  const double expected = referenceCosts(grid, CellWindow::whole(grid), source, false)[grid.index(target)];
  EXPECT_NEAR(cost, expected, floatLabelSlack(expected, moves));
  EXPECT_EQ(cost_with, cost);
  EXPECT_EQ(with_landmarks.expandedCells(), plain.expandedCells());
}

// Across a long wall the octile bound says "10 cells" while the route goes round the wall's far
// end: with landmarks the search takes far fewer cells off its open lists for the same cost.
TEST(Landmarks, SearchAcrossAWallTakesFewerCellsWithThem) {
  CostGrid grid(100, 100, false);
  for (int r = 0; r < 95; ++r) grid.setBlocked(Cell{r, 50}, true);
  const Cell source{5, 45}, target{5, 55};
  MeetingSearch plain, with_landmarks;
  with_landmarks.useLandmarks(4);
  ASSERT_NE(landmarksOnceMade(*with_landmarks.landmarkCache(), grid), nullptr);
  double cost = 0.0, cost_with = 0.0;
  const std::size_t moves = plain.cheapestRoute(grid, source, target, 1, &cost).size();
  const std::size_t moves_with = with_landmarks.cheapestRoute(grid, source, target, 1, &cost_with).size();
  const double expected = referenceCosts(grid, CellWindow::whole(grid), source, false)[grid.index(target)];
  EXPECT_NEAR(cost, expected, floatLabelSlack(expected, moves));
  EXPECT_NEAR(cost_with, expected, floatLabelSlack(expected, moves_with));
  EXPECT_LT(2 * with_landmarks.expandedCells(), plain.expandedCells());
}
