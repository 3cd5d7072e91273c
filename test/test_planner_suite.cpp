// One suite every algorithm must pass (after locusrobotics' global_planner_tests): small
// maps with known answers, every input error, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "eaci/planner.hpp"
#include "test_support.hpp"

using eaci::Algorithm;
using eaci::CostGrid;
using eaci::Cell;
using eaci::PlanStatus;

namespace {

eaci::Parameters quickParameters() {
  eaci::Parameters p;
  p.max_iterations = 15;
  p.ants = 20;
  return p;
}

// 8 x 8 room with an L-shaped wall and a sealed 2 x 2 pocket in the bottom-right corner.
CostGrid room(bool cutting) {
  return CostGrid::fromRows({{0, 0, 0, 0, 0, 0, 0, 0},
                               {0, 0, 0, 0, 0, 0, 0, 0},
                               {0, 0, 1, 1, 1, 1, 0, 0},
                               {0, 0, 0, 0, 0, 1, 0, 0},
                               {0, 0, 0, 0, 0, 1, 0, 0},
                               {0, 0, 0, 0, 0, 0, 1, 1},
                               {0, 0, 0, 0, 0, 1, 0, 0},
                               {0, 0, 0, 0, 0, 1, 0, 0}},
                              cutting);
}

// Every planner: EACI with each island strategy, classic ACO, A*.
struct Planner {
  Algorithm algorithm;
  eaci::IslandStrategy strategy;
  const char* name;
};

class PlannerSuite : public ::testing::TestWithParam<Planner> {
 protected:
  Algorithm algorithm() const { return GetParam().algorithm; }
  eaci::Parameters parameters() const {
    eaci::Parameters p = quickParameters();
    p.island_strategy = GetParam().strategy;
    return p;
  }
};

}  // namespace

TEST_P(PlannerSuite, FindsAValidRouteBetweenFreeCells) {
  const CostGrid grid = room(false);
  const Cell pairs[][2] = {{{0, 0}, {7, 0}}, {{4, 4}, {0, 7}}, {{7, 4}, {0, 0}}, {{3, 3}, {4, 6}}};
  for (const auto& pair : pairs) {
    const auto r = eaci::plan(grid, pair[0], pair[1], algorithm(), parameters());
    ASSERT_EQ(r.status, PlanStatus::kSuccess) << r.error;
    EXPECT_EQ(eaci::test::routeDefect(grid, r.path, pair[0], pair[1]), "");
    EXPECT_NEAR(r.length, eaci::test::countedLength(r.path), 1e-9);
    const double optimum = eaci::cheapestPath(grid, pair[0], pair[1]).length;
    EXPECT_GE(r.length, optimum - 1e-9);
  }
}

TEST_P(PlannerSuite, StraightCorridorGivesTheOnlyRoute) {
  const CostGrid grid = CostGrid::fromRows({{1, 1, 1, 1, 1}, {0, 0, 0, 0, 0}, {1, 1, 1, 1, 1}}, false);
  const auto r = eaci::plan(grid, Cell{1, 0}, Cell{1, 4}, algorithm(), parameters());
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_DOUBLE_EQ(r.length, 4.0);
  EXPECT_DOUBLE_EQ(r.total_turn_deg, 0.0);
  if (algorithm() != Algorithm::kAStar) {
    EXPECT_EQ(r.lost_ants_total, 0);
    EXPECT_EQ(r.iterations_to_converge, 1);
  }
}

TEST_P(PlannerSuite, StartEqualsGoalIsATrivialRoute) {
  const auto r = eaci::plan(room(false), Cell{3, 3}, Cell{3, 3}, algorithm(), parameters());
  ASSERT_TRUE(r.success());
  EXPECT_EQ(r.path, (eaci::CellPath{{3, 3}}));
  EXPECT_DOUBLE_EQ(r.length, 0.0);
}

TEST_P(PlannerSuite, GoalInASealedPocketHasNoPath) {
  const auto r = eaci::plan(room(false), Cell{0, 0}, Cell{7, 7}, algorithm(), parameters());
  EXPECT_EQ(r.status, PlanStatus::kNoPath) << r.error;
}

TEST_P(PlannerSuite, DiagonalGapIsAPassageOnlyWithCornerCutting) {
  // Obstacles touching at their corners split this map in two unless a diagonal may pass between them.
  const std::vector<std::vector<int>> rows = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  const auto strict = eaci::plan(CostGrid::fromRows(rows, false), Cell{0, 0}, Cell{2, 2}, algorithm(),
                                 parameters());
  EXPECT_EQ(strict.status, PlanStatus::kNoPath);
  const auto cutting = eaci::plan(CostGrid::fromRows(rows, true), Cell{0, 0}, Cell{2, 2}, algorithm(),
                                  parameters());
  ASSERT_TRUE(cutting.success()) << cutting.error;
  EXPECT_NEAR(cutting.length, 2.0 + std::sqrt(2.0), 1e-9);
}

TEST_P(PlannerSuite, EveryBadInputGetsAClearError) {
  const CostGrid grid = room(false);
  const auto params = parameters();
  struct Case {
    Cell start, goal;
    PlanStatus status;
  };
  for (const Case& c : {Case{{-1, 0}, {0, 7}, PlanStatus::kStartOffMap},
                        Case{{0, 0}, {8, 0}, PlanStatus::kGoalOffMap},
                        Case{{0, 0}, {0, 99}, PlanStatus::kGoalOffMap},
                        Case{{2, 2}, {0, 7}, PlanStatus::kStartBlocked},
                        Case{{0, 0}, {5, 7}, PlanStatus::kGoalBlocked}}) {
    const auto r = eaci::plan(grid, c.start, c.goal, algorithm(), params);
    EXPECT_EQ(r.status, c.status) << r.error;
    EXPECT_FALSE(r.error.empty());
    EXPECT_TRUE(r.path.empty());
  }
  const auto empty = eaci::plan(CostGrid(), Cell{0, 0}, Cell{0, 0}, algorithm(), params);
  EXPECT_EQ(empty.status, PlanStatus::kInvalidMap) << empty.error;
  const auto empty_view = eaci::plan(eaci::GridView(), Cell{0, 0}, Cell{0, 0}, algorithm(), params);
  EXPECT_EQ(empty_view.status, PlanStatus::kInvalidMap);
  eaci::Parameters bad = params;
  bad.ants = 0;
  const auto invalid = eaci::plan(grid, Cell{0, 0}, Cell{0, 7}, algorithm(), bad);
  EXPECT_EQ(invalid.status, PlanStatus::kInvalidParameters);
  EXPECT_NE(invalid.error.find("ants"), std::string::npos);  // the sentence names the parameter
}

TEST_P(PlannerSuite, OneByOneMaps) {
  const CostGrid free_cell = CostGrid::fromRows({{0}}, false);
  EXPECT_TRUE(eaci::plan(free_cell, Cell{0, 0}, Cell{0, 0}, algorithm(), parameters()).success());
  EXPECT_EQ(eaci::plan(free_cell, Cell{0, 0}, Cell{0, 1}, algorithm(), parameters()).status,
            PlanStatus::kGoalOffMap);
  const CostGrid wall = CostGrid::fromRows({{1}}, false);
  EXPECT_EQ(eaci::plan(wall, Cell{0, 0}, Cell{0, 0}, algorithm(), parameters()).status, PlanStatus::kStartBlocked);
}

TEST_P(PlannerSuite, ReadsCostmapStyleBuffersBottomRowFirst) {
  // costmap_2d layout: row 0 of the buffer is the bottom of the map, 254 lethal, 255 unknown.
  const std::vector<std::uint8_t> buffer = {0, 0, 0,      // bottom
                                            254, 254, 0,  // middle: wall with a gap on the right
                                            0, 0, 255};   // top: unknown in the top-right
  eaci::CellInterpretation costmap{253, 255, eaci::UnknownPolicy::kObstacle};
  const eaci::GridView view(buffer.data(), 3, 3, eaci::RowOrder::kBottomFirst, costmap);
  EXPECT_TRUE(view.isObstacle(Cell{0, 2}));   // top-right, unknown
  EXPECT_TRUE(view.isObstacle(Cell{1, 0}));
  EXPECT_FALSE(view.isObstacle(Cell{2, 0}));  // bottom-left
  // Unknown as obstacle: the only way down, through the top-right corner, is closed.
  EXPECT_EQ(eaci::plan(view, Cell{0, 0}, Cell{2, 0}, algorithm(), parameters()).status, PlanStatus::kNoPath);
  // Unknown as free: right along the top, down the gap, back along the bottom.
  costmap.unknown = eaci::UnknownPolicy::kExpensive;
  const eaci::GridView optimistic(buffer.data(), 3, 3, eaci::RowOrder::kBottomFirst, costmap);
  const auto r = eaci::plan(optimistic, Cell{0, 0}, Cell{2, 0}, algorithm(), parameters());
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_NEAR(r.length, 6.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(AllPlanners, PlannerSuite,
                         ::testing::Values(Planner{Algorithm::kEaci, eaci::IslandStrategy::kGeodesic, "eaci_geodesic"},
                                           Planner{Algorithm::kEaci, eaci::IslandStrategy::kPaper, "eaci_paper"},
                                           Planner{Algorithm::kAco, eaci::IslandStrategy::kGeodesic, "aco"},
                                           Planner{Algorithm::kAStar, eaci::IslandStrategy::kGeodesic, "astar"}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(PlannerDeterminism, SameSeedSameResultOnAnyThreadCount) {
  // 40 x 40: colonies on fewer than kCellsForWorkers cells walk on one thread whatever asked.
  const CostGrid grid = eaci::test::paperMap("paper-40x40.txt", true);
  static_assert(40 * 40 >= eaci::kCellsForWorkers, "the colony must use the threads it is given");
  for (Algorithm algorithm : {Algorithm::kEaci, Algorithm::kAco}) {
    eaci::Parameters p;
    p.island_strategy = eaci::IslandStrategy::kPaper;  // more lost ants: differences would show
    p.allow_corner_cutting = true;
    p.max_iterations = 30;
    p.seed = 7;
    p.threads = 1;
    const auto one = eaci::plan(grid, Cell{0, 0}, Cell{39, 39}, algorithm, p);
    p.threads = 2;
    const auto two = eaci::plan(grid, Cell{0, 0}, Cell{39, 39}, algorithm, p);
    p.threads = 3;
    const auto three = eaci::plan(grid, Cell{0, 0}, Cell{39, 39}, algorithm, p);
    p.threads = 1;
    const auto again = eaci::plan(grid, Cell{0, 0}, Cell{39, 39}, algorithm, p);
    for (const auto* other : {&two, &three, &again}) {
      EXPECT_EQ(one.path, other->path);
      EXPECT_EQ(one.lost_ants_per_iteration, other->lost_ants_per_iteration);
      EXPECT_EQ(one.iteration_best_cost, other->iteration_best_cost);
    }
    p.seed = 8;
    const auto other_seed = eaci::plan(grid, Cell{0, 0}, Cell{39, 39}, algorithm, p);
    EXPECT_NE(one.lost_ants_per_iteration, other_seed.lost_ants_per_iteration);
  }
}

// From 256 x 256 cells geodesic EACI finds its route by the search that meets in the middle,
// whose two sides run on two threads when it has them: the result is still the same on any
// thread count, and as cheap as A*'s within the colony's early stop.
TEST(PlannerDeterminism, LargeMapSameResultOnAnyThreadCount) {
  CostGrid grid(300, 260, false);
  for (int r = 0; r < grid.height(); ++r)
    for (int c = 0; c < grid.width(); ++c) {
      if (c % 60 == 30 && (r + c) % 130 > 12) grid.setBlocked(Cell{r, c}, true);  // walls with doors
      else grid.setCost(Cell{r, c}, static_cast<std::uint8_t>((r * 7 + c * 13) % 90));
    }
  const Cell start{5, 3}, goal{250, 290};
  eaci::Parameters p;
  p.max_iterations = 10;
  p.early_stop_iterations = 3;
  p.stop_gap = 0.01;
  p.threads = 1;
  const auto one = eaci::plan(grid, start, goal, Algorithm::kEaci, p);
  ASSERT_TRUE(one.success()) << one.error;
  EXPECT_EQ(eaci::test::routeDefect(grid, one.path, start, goal), "");
  const double optimum = eaci::cheapestPath(grid, start, goal).cost;
  EXPECT_GE(one.cost, optimum - 1e-9);
  EXPECT_LE(one.cost, 1.03 * optimum);
  for (int threads : {2, 0}) {
    p.threads = threads;
    const auto other = eaci::plan(grid, start, goal, Algorithm::kEaci, p);
    EXPECT_EQ(one.path, other.path) << threads << " threads";
    EXPECT_EQ(one.islands, other.islands) << threads << " threads";
    EXPECT_EQ(one.lost_ants_per_iteration, other.lost_ants_per_iteration) << threads << " threads";
  }
}

// A kept PlannerWorkspace (the ROS node's and plugin's) changes nothing but where the memory
// and threads come from: plans one after another on maps that grow and shrink, geodesic EACI,
// the paper's islands and classic ACO in turn, on two threads, give what fresh plans give.
TEST(PlannerDeterminism, KeptWorkspaceGivesWhatFreshPlansGive) {
  CostGrid large(300, 260, false);
  for (int r = 0; r < large.height(); ++r)
    for (int c = 0; c < large.width(); ++c) {
      if (c % 60 == 30 && (r + c) % 130 > 12) large.setBlocked(Cell{r, c}, true);
      else large.setCost(Cell{r, c}, static_cast<std::uint8_t>((r * 7 + c * 13) % 90));
    }
  const CostGrid paper = eaci::test::paperMap("paper-40x40.txt", true);  // the paper's move rule
  struct Request {
    const CostGrid* grid;
    Cell start, goal;
    Algorithm algorithm;
    eaci::IslandStrategy islands;
  };
  const Request requests[] = {
      {&large, Cell{5, 3}, Cell{250, 290}, Algorithm::kEaci, eaci::IslandStrategy::kGeodesic},
      {&paper, Cell{0, 0}, Cell{39, 39}, Algorithm::kEaci, eaci::IslandStrategy::kGeodesic},
      {&paper, Cell{0, 0}, Cell{39, 39}, Algorithm::kEaci, eaci::IslandStrategy::kPaper},
      {&large, Cell{200, 10}, Cell{20, 160}, Algorithm::kEaci, eaci::IslandStrategy::kGeodesic},
      {&paper, Cell{0, 0}, Cell{39, 39}, Algorithm::kAco, eaci::IslandStrategy::kGeodesic},
      {&large, Cell{5, 3}, Cell{250, 290}, Algorithm::kEaci, eaci::IslandStrategy::kGeodesic},
  };
  eaci::PlannerWorkspace workspace;
  for (const Request& q : requests) {
    eaci::Parameters p;
    p.max_iterations = 12;
    p.early_stop_iterations = 4;
    p.island_strategy = q.islands;
    p.threads = 2;
    p.seed = 3;
    eaci::PlanOptions kept;
    kept.workspace = &workspace;
    kept.record_pheromone = true;
    eaci::PlanOptions fresh;
    fresh.record_pheromone = true;
    const auto with_workspace = eaci::plan(*q.grid, q.start, q.goal, q.algorithm, p, kept);
    const auto without = eaci::plan(*q.grid, q.start, q.goal, q.algorithm, p, fresh);
    ASSERT_TRUE(without.success()) << without.error;
    EXPECT_EQ(with_workspace.path, without.path);
    EXPECT_EQ(with_workspace.islands, without.islands);
    EXPECT_EQ(with_workspace.lost_ants_per_iteration, without.lost_ants_per_iteration);
    EXPECT_EQ(with_workspace.iteration_best_cost, without.iteration_best_cost);
    EXPECT_EQ(with_workspace.pheromone, without.pheromone);
  }
}

TEST(PlannerLimits, RefusesAMapWhosePheromoneWouldExceedTheCap) {
  // Never allocated: the check runs on the dimensions. Only colonies that keep pheromone on
  // the whole map are capped: classic ACO, the paper's islands and region_margin 0 (geodesic
  // EACI keeps it for its region around the route; A* has none).
  const std::size_t side = 5000;  // 25 M cells * 128 B = 3 GiB > 2 GiB
  const CostGrid grid(static_cast<int>(side), static_cast<int>(side), false);
  eaci::Parameters paper = quickParameters();
  paper.island_strategy = eaci::IslandStrategy::kPaper;
  eaci::Parameters whole_map = quickParameters();
  whole_map.region_margin = 0;
  for (const auto& [algorithm, params] : {std::pair<Algorithm, eaci::Parameters>{Algorithm::kAco, quickParameters()},
                                          {Algorithm::kEaci, paper}, {Algorithm::kEaci, whole_map}}) {
    const auto r = eaci::plan(grid, Cell{0, 0}, Cell{0, 1}, algorithm, params);
    EXPECT_EQ(r.status, PlanStatus::kInvalidMap) << r.error;
    EXPECT_NE(r.error.find("MiB"), std::string::npos) << r.error;  // the sentence names the cap
  }
}

TEST(PlannerLimits, StopCheckEndsTheRunAndKeepsTheBestRoute) {
  const CostGrid grid = eaci::test::paperMap("paper-20x20.txt", true);
  eaci::PlanOptions options;
  options.should_stop = [](int done) { return done >= 3; };
  const auto r = eaci::plan(grid, Cell{0, 0}, Cell{19, 19}, Algorithm::kEaci, eaci::Parameters{}, options);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(r.iterations_run, 3);
}

TEST(PlannerLimits, StopCheckDuringSetUpGivesTheSearchRouteWithGeodesicIslands) {
  // A stop check that is true from the start ends the plan right after the islands, before any
  // ant walks; geodesic EACI then returns the cheapest route its islands sit on (A*'s cost).
  const CostGrid grid = eaci::test::paperMap("paper-20x20.txt", true);
  eaci::PlanOptions options;
  options.should_stop = [](int) { return true; };
  const auto r = eaci::plan(grid, Cell{0, 0}, Cell{19, 19}, Algorithm::kEaci, eaci::Parameters{}, options);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_TRUE(r.interrupted);
  EXPECT_TRUE(r.route_from_search);
  EXPECT_EQ(r.iterations_run, 0);
  EXPECT_NEAR(r.cost, eaci::cheapestPath(grid, Cell{0, 0}, Cell{19, 19}).cost, 1e-9);
  EXPECT_EQ(eaci::test::routeDefect(grid, r.path, Cell{0, 0}, Cell{19, 19}), "");
}

namespace {
// An ant that wanders: one ant, one iteration, no heuristic (beta 0).
eaci::Parameters oneWanderingAnt() {
  eaci::Parameters p;
  p.ants = 1;
  p.max_iterations = 1;
  p.beta = 0.0;
  return p;
}
eaci::PlanOptions neverWorseThanSearch() {
  eaci::PlanOptions options;
  options.never_worse_than_search = true;
  return options;
}
}  // namespace

// One ant, one iteration, no heuristic (beta 0): the ant wanders, and where it still arrives its
// route is longer than the only cheapest one, the diagonal of the open 12 x 12 map, 11 sqrt 2.
// never_worse_than_search then returns the diagonal its islands sit on instead.
TEST(PlannerLimits, NeverWorseThanSearchReturnsTheSearchRouteInsteadOfALuckyAntsDetour) {
  const CostGrid grid(12, 12, false);
  const double diagonal = 11 * std::sqrt(2.0);
  eaci::Parameters p = oneWanderingAnt();
  const eaci::PlanOptions guarded = neverWorseThanSearch();
  int detours = 0;
  for (unsigned seed = 1; seed <= 10; ++seed) {
    p.seed = seed;
    const auto walked = eaci::plan(grid, Cell{0, 0}, Cell{11, 11}, Algorithm::kEaci, p);
    const auto kept = eaci::plan(grid, Cell{0, 0}, Cell{11, 11}, Algorithm::kEaci, p, guarded);
    ASSERT_TRUE(walked.success() && kept.success()) << walked.error << kept.error;
    EXPECT_NEAR(kept.cost, diagonal, 1e-9) << "seed " << seed;
    EXPECT_EQ(eaci::test::routeDefect(grid, kept.path, Cell{0, 0}, Cell{11, 11}), "");
    if (walked.cost > diagonal + 1e-9) {
      ++detours;
      EXPECT_TRUE(kept.route_from_search) << "seed " << seed;
      EXPECT_DOUBLE_EQ(kept.colony_combined_cost, walked.combined_cost) << "seed " << seed;
    } else {  // the ant took the diagonal, or was lost (then the search's route anyway)
      EXPECT_EQ(kept.path, walked.path) << "seed " << seed;
      EXPECT_FALSE(std::isfinite(kept.colony_combined_cost)) << "seed " << seed;
    }
  }
  EXPECT_GT(detours, 0);  // the case the option is for came up
}

// The guard compares the objective the colony answers to, cost + turn_cost x turning. A cell of
// cost 20 in the middle of a 3 x 11 corridor: through it 10 + 3 x 20 / 50 = 11.2 with no turn;
// round it 8 + 2 sqrt 2 = 10.83 with 180 deg (45 + 90 + 45) or, along the edge row, 90 deg. At
// turn_cost 1 the straight way is the optimum (11.2 against 10.83 + pi and 10.83 + pi / 2), and
// with turn_cost > 0 the islands sit on that optimum (the exact heading search). One wandering
// ant (as above) arrives with routes that can cost less than 11.2 and turn more: they are
// replaced too.
TEST(PlannerLimits, NeverWorseThanSearchWeighsTheTurnsToo) {
  CostGrid grid(11, 3, false);
  grid.setCost(Cell{1, 5}, 20);
  eaci::Parameters p = oneWanderingAnt();
  p.turn_cost = 1.0;
  const eaci::PlanOptions guarded = neverWorseThanSearch();
  int cheaper_but_turning = 0;
  for (unsigned seed = 1; seed <= 30; ++seed) {
    p.seed = seed;
    const auto walked = eaci::plan(grid, Cell{1, 0}, Cell{1, 10}, Algorithm::kEaci, p);
    const auto kept = eaci::plan(grid, Cell{1, 0}, Cell{1, 10}, Algorithm::kEaci, p, guarded);
    ASSERT_TRUE(walked.success() && kept.success()) << walked.error << kept.error;
    EXPECT_NEAR(kept.combined_cost, 11.2, 1e-9) << "seed " << seed;
    EXPECT_NEAR(kept.cost, 11.2, 1e-9) << "seed " << seed;
    cheaper_but_turning += walked.cost < 11.2 - 1e-9;
  }
  EXPECT_GT(cheaper_but_turning, 0);  // a route a guard by cost alone would have kept came up
}

TEST(PlannerLimits, StopCheckDuringSetUpEndsWithoutARouteAndSaysSo) {
  // The paper's islands have no search route to fall back on: a stop check that is true from
  // the start ends the plan before any ant walks, even with the pheromone picture asked for.
  const CostGrid grid = eaci::test::paperMap("paper-20x20.txt", true);
  eaci::PlanOptions options;
  options.record_pheromone = true;
  int asked = 0;
  options.should_stop = [&asked](int) {
    ++asked;
    return true;
  };
  eaci::Parameters paper;
  paper.island_strategy = eaci::IslandStrategy::kPaper;
  const auto r = eaci::plan(grid, Cell{0, 0}, Cell{19, 19}, Algorithm::kEaci, paper, options);
  EXPECT_EQ(r.status, PlanStatus::kStopped) << r.error;
  EXPECT_FALSE(r.route_from_search);
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(r.iterations_run, 0);
  EXPECT_EQ(asked, 1);  // right after the islands
  EXPECT_TRUE(r.pheromone.empty());
}

TEST(PlannerLimits, EarlyStopAfterIterationsWithoutImprovement) {
  const CostGrid grid = eaci::test::paperMap("paper-30x30.txt", true);
  eaci::Parameters p;
  p.island_strategy = eaci::IslandStrategy::kPaper;  // knows no cheapest cost: only stagnation stops it
  p.allow_corner_cutting = true;
  p.early_stop_iterations = 5;
  const auto r = eaci::plan(grid, Cell{29, 0}, Cell{0, 29}, Algorithm::kEaci, p);
  ASSERT_TRUE(r.success());
  EXPECT_TRUE(r.stopped_early);
  EXPECT_EQ(r.iterations_run, r.iterations_to_converge + 5);
}

// stop_gap ends a run as soon as its best route is within the gap of A*'s cost (the reference,
// computed here on its own), and only with early stopping on.
TEST(PlannerLimits, StopGapEndsTheRunOnceTheRouteIsAsCheapAsAStars) {
  const CostGrid grid = eaci::test::paperMap("paper-30x30.txt", true);
  const Cell start{29, 0}, goal{0, 29};
  const double optimum = eaci::cheapestPath(grid, start, goal).cost;
  eaci::Parameters p;
  p.allow_corner_cutting = true;
  p.early_stop_iterations = 1000;  // never by stagnation within max_iterations
  p.stop_gap = 0.0;
  const auto r = eaci::plan(grid, start, goal, Algorithm::kEaci, p);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_NEAR(r.cost, optimum, 1e-9);
  EXPECT_TRUE(r.stopped_early);
  EXPECT_EQ(r.iterations_run, r.iterations_to_converge);  // the iteration that reached it is the last
  EXPECT_LT(r.iterations_run, p.max_iterations);
}

// With stop_gap in force an iteration ends after the first wave of 2 ants that brings a route
// within the gap. In a corridor one cell wide every ant walks the only route, so the first
// wave ends the run; without early stopping every iteration walks all m ants.
TEST(PlannerLimits, StopGapEndsTheIterationAfterTheFirstWaveOfAnts) {
  CostGrid grid(40, 3, false);  // 40 columns, 3 rows
  for (int c = 0; c < 40; ++c) {
    grid.setBlocked(Cell{0, c}, true);
    grid.setBlocked(Cell{2, c}, true);
  }
  const Cell start{1, 0}, goal{1, 39};
  eaci::Parameters p;
  p.max_iterations = 3;
  p.early_stop_iterations = 5;
  p.stop_gap = 0.0;
  const auto waved = eaci::plan(grid, start, goal, Algorithm::kEaci, p);
  ASSERT_TRUE(waved.success()) << waved.error;
  EXPECT_DOUBLE_EQ(waved.length, 39.0);
  EXPECT_TRUE(waved.stopped_early);
  EXPECT_EQ(waved.ants_per_iteration, std::vector<int>({2}));
  EXPECT_EQ(waved.lost_ants_per_iteration, std::vector<int>({0}));
  p.early_stop_iterations = 0;  // the paper's protocol: every ant of every iteration
  const auto all = eaci::plan(grid, start, goal, Algorithm::kEaci, p);
  ASSERT_TRUE(all.success()) << all.error;
  EXPECT_EQ(all.ants_per_iteration, std::vector<int>({50, 50, 50}));
  EXPECT_EQ(all.path, waved.path);
}

TEST(PlannerLimits, StopGapAcceptsARouteWithinTheGapOnACostMap) {
  // A 40 x 40 room whose cells cost more towards a wall down the middle (a door at the bottom).
  CostGrid grid(40, 40, false);
  for (int r = 0; r < 40; ++r)
    for (int c = 0; c < 40; ++c) grid.setCost(Cell{r, c}, static_cast<std::uint8_t>(std::max(0, 200 - 25 * std::abs(c - 20))));
  for (int r = 0; r < 34; ++r) grid.setBlocked(Cell{r, 20}, true);
  const Cell start{2, 2}, goal{2, 37};
  const double optimum = eaci::cheapestPath(grid, start, goal).cost;
  eaci::Parameters p;
  p.early_stop_iterations = 1000;
  p.stop_gap = 0.05;
  const auto r = eaci::plan(grid, start, goal, Algorithm::kEaci, p);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_LE(r.cost, 1.05 * optimum + 1e-9);
  EXPECT_TRUE(r.stopped_early);
  EXPECT_EQ(r.iterations_run, r.iterations_to_converge);
  // Early stopping off (the paper's protocol): every iteration runs, whatever stop_gap says.
  p.early_stop_iterations = 0;
  p.max_iterations = 30;
  const auto all = eaci::plan(grid, start, goal, Algorithm::kEaci, p);
  ASSERT_TRUE(all.success()) << all.error;
  EXPECT_FALSE(all.stopped_early);
  EXPECT_EQ(all.iterations_run, 30);
}

TEST_P(PlannerSuite, AllObstacleMapIsAClearError) {
  const CostGrid walls = CostGrid::fromRows(std::vector<std::vector<int>>(5, std::vector<int>(5, 1)), false);
  const auto r = eaci::plan(walls, Cell{0, 0}, Cell{4, 4}, algorithm(), parameters());
  EXPECT_EQ(r.status, PlanStatus::kStartBlocked) << r.error;
}

TEST_P(PlannerSuite, MoreIslandsThanTheRouteHasCells) {
  // N far above the route's length: r_s drops below one cell; planning still works.
  eaci::Parameters p = parameters();
  p.islands = 100000;
  const CostGrid grid = room(false);
  const auto r = eaci::plan(grid, Cell{0, 0}, Cell{7, 0}, algorithm(), p);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_EQ(eaci::test::routeDefect(grid, r.path, Cell{0, 0}, Cell{7, 0}), "");
}

TEST_P(PlannerSuite, StartAndGoalOnTheMapEdge) {
  const CostGrid grid = room(false);
  const auto r = eaci::plan(grid, Cell{0, 7}, Cell{7, 0}, algorithm(), parameters());  // two corners
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_EQ(eaci::test::routeDefect(grid, r.path, Cell{0, 7}, Cell{7, 0}), "");
}

TEST(PlannerThreads, AntsOnFourThreadsOnEveryPaperMap) {
  // Run under ThreadSanitizer by scripts/sanitize.sh: the ants of an iteration share the
  // pheromone (read-only) and write only their own routes.
  for (const auto& pc : eaci::test::paperCases()) {
    const CostGrid grid = eaci::test::paperMap(pc.file, true);
    for (Algorithm algorithm : {Algorithm::kEaci, Algorithm::kAco}) {
      eaci::Parameters p;
      p.allow_corner_cutting = true;
      p.max_iterations = 10;
      p.threads = 4;
      const auto four = eaci::plan(grid, pc.start, pc.goal, algorithm, p);
      p.threads = 1;
      const auto one = eaci::plan(grid, pc.start, pc.goal, algorithm, p);
      EXPECT_EQ(four.path, one.path) << pc.file;
      EXPECT_EQ(four.lost_ants_per_iteration, one.lost_ants_per_iteration) << pc.file;
    }
  }
}
