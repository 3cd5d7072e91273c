// The colonies score turning (issue #30): with turn_cost > 0 an ant's L_k is its combined cost,
// the heuristic prices the candidate move's turn, and the colonies reach the combined optimum.
// Expectations are hand-computed, or from the exact front (src/bench/exact_front.hpp, a Dijkstra
// written apart from the planners and checked against a brute force in test_exact_front.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../src/bench/exact_front.hpp"
#include "eaci/aco/ant_walk.hpp"
#include "eaci/grid/inflation.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/planner.hpp"
#include "test_support.hpp"

using eaci::AntRoute;
using eaci::Cell;
using eaci::CostGrid;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kEast = 0, kNorth = 2, kNorthEast = 1;
}  // namespace

TEST(ColonyTurns, AnAntsRouteCostCountsItsTurnsAtTheirPrice) {
  // A one-cell-wide L: (2,0) -> (2,3) east, then north to (0,3). Every ant that arrives walks
  // these five straight moves with one right angle: cost 5 + turn_cost x pi/2.
  const CostGrid grid = CostGrid::fromRows({{1, 1, 1, 0}, {1, 1, 1, 0}, {0, 0, 0, 0}}, false);
  const eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  for (double turn_cost : {0.0, 0.3, 2.0}) {
    eaci::WalkSetup setup(grid, field, {Cell{2, 0}, Cell{0, 3}}, eaci::HeuristicRule::kTurningAware, 7.0, 0.5);
    setup.priceTurns(turn_cost);
    eaci::AntWalker walker;
    eaci::SplitMix64 rng = eaci::antStream(1, 1, 0);
    AntRoute route;
    walker.walk(setup, rng, route);
    ASSERT_TRUE(route.complete);
    EXPECT_NEAR(route.length, 5.0, 1e-12);
    EXPECT_NEAR(route.cost, 5.0 + turn_cost * kPi / 2, 1e-12) << "turn_cost " << turn_cost;
  }
}

TEST(ColonyTurns, AnAntsRouteCostCountsTheTurnsAtItsEnds) {
  // The L of the test above with headings at its ends: facing north at S, the first move (east)
  // turns 90 degrees; facing west at G, the last move (north) turns 90 more. Every ant walks
  // the same route: cost 5 + turn_cost x (pi/2 + pi/2 + pi/2). The plan's own combined cost,
  // whatever the colony, prices the same three turns.
  const CostGrid grid = CostGrid::fromRows({{1, 1, 1, 0}, {1, 1, 1, 0}, {0, 0, 0, 0}}, false);
  const eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  eaci::EndHeadings ends;
  ends.start = kPi / 2;
  ends.goal = kPi;
  const double turn_cost = 0.3;
  eaci::WalkSetup setup(grid, field, {Cell{2, 0}, Cell{0, 3}}, eaci::HeuristicRule::kTurningAware, 7.0, 0.5);
  setup.priceTurns(turn_cost, ends);
  eaci::AntWalker walker;
  eaci::SplitMix64 rng = eaci::antStream(1, 1, 0);
  AntRoute route;
  walker.walk(setup, rng, route);
  ASSERT_TRUE(route.complete);
  EXPECT_NEAR(route.cost, 5.0 + turn_cost * 3 * kPi / 2, 1e-12);
  eaci::Parameters p;
  p.turn_cost = turn_cost;
  p.max_iterations = 5;
  eaci::PlanOptions options;
  options.end_headings = ends;
  for (eaci::Algorithm algorithm :
       {eaci::Algorithm::kEaci, eaci::Algorithm::kAco, eaci::Algorithm::kMaaco, eaci::Algorithm::kAStar}) {
    const eaci::PlanResult r = eaci::plan(grid, Cell{2, 0}, Cell{0, 3}, algorithm, p, options);
    ASSERT_TRUE(r.success()) << r.error;
    EXPECT_NEAR(r.combined_cost, 5.0 + turn_cost * 3 * kPi / 2, 1e-12) << eaci::toString(algorithm);
  }
}

TEST(ColonyTurns, TheGoalHeadingPicksTheColoniesLastLeg) {
  // test_heading_search.cpp's hand case: on 3 x 5 open cells from the bottom left to the top
  // right, the shortest routes NE NE E E and E E NE NE turn 45 degrees each; a goal heading of
  // 45 degrees adds nothing to the second and 45 degrees to the first. Every colony must find
  // the second: combined cost 2 + 2 sqrt 2 + turn_cost x pi/4.
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}}, false);
  eaci::PlanOptions options;
  options.end_headings.goal = kPi / 4;
  for (eaci::Algorithm algorithm : {eaci::Algorithm::kEaci, eaci::Algorithm::kAco}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      eaci::Parameters p;
      p.turn_cost = 1.0;
      p.seed = seed;
      const eaci::PlanResult r = eaci::plan(grid, Cell{2, 0}, Cell{0, 4}, algorithm, p, options);
      ASSERT_TRUE(r.success()) << r.error;
      EXPECT_NEAR(r.combined_cost, 2.0 + 2.0 * std::sqrt(2.0) + kPi / 4, 1e-9)
          << eaci::toString(algorithm) << " seed " << seed;
      EXPECT_EQ(r.path.back(), (Cell{0, 4}));
      EXPECT_EQ(r.path[r.path.size() - 2], (Cell{1, 3})) << eaci::toString(algorithm) << " seed " << seed;
    }
  }
}

TEST(ColonyTurns, TheHeuristicPricesTheCandidateMovesTurn) {
  // Heading east at (2,2) of an open 5 x 9 map: going on east turns nothing, north-east 45
  // degrees, north 90. d_jg + sigma (Eq. 16-17, epsilon per 45-degree step) gains turn_cost x
  // the turn in radians, plus the least turn any route from the cell entered, heading the
  // move's way, needs to reach the goal (0,8): from (2,3) heading east, 45 degrees up to it;
  // from (1,3) heading north-east, 45 down to it; from (1,2) heading north, 90. Without a price
  // it is as before. The goal is no neighbour of these cells (its last step: the next test).
  const CostGrid grid = CostGrid::fromRows(std::vector<std::vector<int>>(5, std::vector<int>(9, 0)), false);
  const eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  const double epsilon = 0.5, turn_cost = 0.8;
  const Cell here{2, 2}, goal{0, 8};
  eaci::WalkSetup plain(grid, field, {Cell{4, 0}, goal}, eaci::HeuristicRule::kTurningAware, 7.0, epsilon);
  eaci::WalkSetup priced(grid, field, {Cell{4, 0}, goal}, eaci::HeuristicRule::kTurningAware, 7.0, epsilon);
  priced.priceTurns(turn_cost);
  const auto region_cell = [&](const eaci::WalkSetup& s, int dir) {
    return s.region.regionIndex(eaci::step(here, dir));
  };
  const auto distance_from = [&](int dir) {  // Euclidean d_jg from the cell the move enters
    const Cell to = eaci::step(here, dir);
    return std::hypot(to.row - goal.row, to.col - goal.col);
  };
  const struct { int dir; int steps; int ahead; } moves[] = {{kEast, 0, 1}, {kNorthEast, 1, 1}, {kNorth, 2, 2}};
  for (const auto& m : moves) {
    EXPECT_NEAR(plain.heuristicDistance(here, region_cell(plain, m.dir), 1, kEast, m.dir),
                distance_from(m.dir) + epsilon * m.steps, 1e-6);
    EXPECT_NEAR(priced.heuristicDistance(here, region_cell(priced, m.dir), 1, kEast, m.dir),
                distance_from(m.dir) + epsilon * m.steps + turn_cost * (m.steps + m.ahead) * kPi / 4, 1e-6);
  }
  // The first move of a route turns nothing, priced or not; the turn still ahead is priced.
  EXPECT_NEAR(priced.heuristicDistance(here, region_cell(priced, kNorth), 1, -1, kNorth),
              distance_from(kNorth) + turn_cost * 2 * kPi / 4, 1e-6);
}

TEST(ColonyTurns, TheHeuristicLooksAheadToTheTurnsAtTheLegsEnd) {
  // Islands S = (3,0), (1,1), E = (0,2) on the route (3,0) N (2,0) NE (1,1) NE (0,2): the route
  // leaves (1,1) heading north-east. From S, north to (2,0) commits the ant to NE into (1,1)
  // (a 45-degree turn) and on NE (none): 1 step. North-east to (2,1) commits it to N into (1,1)
  // (45) and NE out (45): 2 steps. Entering an island prices the turn onto its exit direction.
  const CostGrid grid = CostGrid::fromRows(std::vector<std::vector<int>>(4, std::vector<int>(4, 0)), false);
  const eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  const double turn_cost = 0.8, epsilon = 0.5;
  const std::vector<Cell> islands{{3, 0}, {1, 1}, {0, 2}};
  eaci::WalkSetup plain(grid, field, islands, eaci::HeuristicRule::kTurningAware, 7.0, epsilon);
  eaci::WalkSetup priced(grid, field, islands, eaci::HeuristicRule::kTurningAware, 7.0, epsilon);
  priced.priceTurns(turn_cost);
  priced.setExitDirections({{3, 0}, {2, 0}, {1, 1}, {0, 2}});
  const auto extra = [&](Cell from, int previous_dir, int dir) {
    const std::uint32_t next = priced.region.regionIndex(eaci::step(from, dir));
    return priced.heuristicDistance(from, next, 1, previous_dir, dir) -
           plain.heuristicDistance(from, next, 1, previous_dir, dir);
  };
  EXPECT_NEAR(extra(Cell{3, 0}, -1, kNorth), turn_cost * kPi / 4, 1e-6);
  EXPECT_NEAR(extra(Cell{3, 0}, -1, kNorthEast), turn_cost * kPi / 2, 1e-6);
  // Into the island from (2,1) heading north: the turn onto NE out of it.
  EXPECT_NEAR(extra(Cell{2, 1}, kNorthEast, kNorth), turn_cost * (kPi / 4 + kPi / 4), 1e-6);
  // Into it from (2,0) heading north, moving north-east: the move's own turn, none out.
  EXPECT_NEAR(extra(Cell{2, 0}, kNorth, kNorthEast), turn_cost * kPi / 4, 1e-6);
  // Farther off, the least turning on the way: from S east to (3,1), the island two rows due
  // north needs a 90-degree turn of any route heading east (turnStepsAtLeast), more than the 45
  // onto its exit direction: 2 steps.
  EXPECT_NEAR(extra(Cell{3, 0}, -1, kEast), turn_cost * kPi / 2, 1e-6);
  // From (3,1) on east to (3,2), past it: the island is up and back to the left, more than 90
  // degrees from east (3 steps), against 1 step onto its exit direction.
  EXPECT_NEAR(extra(Cell{3, 1}, kEast, kEast), turn_cost * 3 * kPi / 4, 1e-6);
}

TEST(ColonyTurns, ADearTurnMakesEveryColonyTakeTheDearerStraightRoute) {
  // Row 0 from S to G runs through three cells of cost 50 (a move into one costs 4 x its length
  // under neutral 50, factor 3): straight on costs 4 + 4 + 4 + 1 = 13 and turns nothing. Round
  // them through row 1 costs 2 + 2 sqrt 2 and turns at least 90 degrees. Optimum:
  // min(13, 2 + 2 sqrt 2 + turn_cost x pi/2): round at turn_cost 0 and 1, straight at 10.
  CostGrid grid(5, 2, false);
  for (int c = 1; c <= 3; ++c) grid.setCost(Cell{0, c}, 50);
  const double round = 2.0 + 2.0 * std::sqrt(2.0);
  // (MAACO's heuristic sees no cell costs: it misses the cheap round route even unpriced.)
  for (eaci::Algorithm algorithm : {eaci::Algorithm::kEaci, eaci::Algorithm::kAco}) {
    for (double turn_cost : {0.0, 1.0, 10.0}) {
      const double optimum = std::min(13.0, round + turn_cost * kPi / 2);
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        eaci::Parameters p;
        p.turn_cost = turn_cost;
        p.seed = seed;
        p.max_iterations = 30;
        const eaci::PlanResult r = eaci::plan(grid, Cell{0, 0}, Cell{0, 4}, algorithm, p);
        ASSERT_EQ(r.status, eaci::PlanStatus::kSuccess) << r.error;
        EXPECT_NEAR(r.combined_cost, optimum, 1e-9)
            << eaci::toString(algorithm) << " turn_cost " << turn_cost << " seed " << seed;
      }
    }
  }
}

TEST(ColonyTurns, EaciReachesTheCombinedOptimumOfThePaperMapsFromTheExactFront) {
  // The combined optimum, min over routes of length + turn_cost x turn, is reached on the exact
  // front (a route off it is dominated); on these binary maps cost is length. EACI with the
  // project's defaults (geodesic islands) and the paper tables' move rule, seeds 1-3.
  for (const eaci::test::PaperCase& pc : eaci::test::paperCases()) {
    const CostGrid grid = eaci::test::paperMap(pc.file, true);
    const std::vector<eaci_bench::FrontPoint> front = eaci_bench::exactFront(grid, pc.start, pc.goal, 40);
    ASSERT_FALSE(front.empty()) << pc.file;
    for (double turn_cost : {0.2, 0.5, 1.0}) {
      double optimum = std::numeric_limits<double>::infinity();
      for (const eaci_bench::FrontPoint& f : front)
        optimum = std::min(optimum, f.length + turn_cost * f.turn_steps * kPi / 4);
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        eaci::Parameters p;
        p.allow_corner_cutting = true;
        p.turn_cost = turn_cost;
        p.seed = seed;
        const eaci::PlanResult r = eaci::plan(grid, pc.start, pc.goal, eaci::Algorithm::kEaci, p);
        ASSERT_EQ(r.status, eaci::PlanStatus::kSuccess) << r.error;
        EXPECT_LE(r.combined_cost, optimum * 1.01) << pc.file << " turn_cost " << turn_cost << " seed " << seed;
        EXPECT_GE(r.combined_cost, optimum - 1e-9) << pc.file;  // nothing beats the optimum
      }
    }
  }
}

TEST(ColonyTurns, EaciReachesTheCombinedOptimumThroughTheLabsInflatedGaps) {
  // The lab map inflated as the lab's costmap is (config/costmap_common_params.yaml: radius
  // 0.55 m, scaling 5, the car's inscribed radius with padding 0.177 m), turns dear (the lab
  // config's turn_cost 20): long routes of many turns through gaps whose middles cost several
  // times a free cell. The exact heading search (test_heading_search.cpp, against a brute
  // force) gives the optimum; EACI, with the defaults, must come within 1 % of it.
  const eaci::OccupancyMap map = eaci::loadMap(EACI_SOURCE_DIR "/maps/lab.yaml");
  eaci::InflationParameters inflation;
  inflation.inflation_radius = 0.55;
  inflation.inscribed_radius = 0.177;
  inflation.cost_scaling_factor = 5.0;
  const std::vector<std::uint8_t> costs =
      eaci::inflatedCosts(map.view(eaci::UnknownPolicy::kObstacle), map.resolution, inflation);
  const eaci::GridView view(costs.data(), map.width, map.height, eaci::RowOrder::kTopFirst,
                            eaci::inflatedCostsInterpretation(false));
  const Cell start = *map.worldToCell({4.2, 0.5});
  // The second goal with headings at both ends, as the robot plans (facing west at the start,
  // south at the goal, as eaci_plan --start-yaw 180 --goal-yaw -90).
  eaci::PlanOptions with_ends;
  with_ends.end_headings = {kPi, -kPi / 2};
  for (const auto& [goal_xy, options] : {std::pair<Eigen::Vector2d, eaci::PlanOptions>{{1.1, 2.2}, {}},
                                         {{0.5, 2.6}, {}}, {{0.5, 2.6}, with_ends}}) {
    const Cell goal = *map.worldToCell(goal_xy);
    eaci::Parameters p;
    p.turn_cost = 20.0;
    const eaci::PlanResult exact = eaci::plan(view, start, goal, eaci::Algorithm::kAStar, p, options);
    ASSERT_EQ(exact.status, eaci::PlanStatus::kSuccess) << exact.error;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      p.seed = seed;
      const eaci::PlanResult r = eaci::plan(view, start, goal, eaci::Algorithm::kEaci, p, options);
      ASSERT_EQ(r.status, eaci::PlanStatus::kSuccess) << r.error;
      EXPECT_LE(r.combined_cost, exact.combined_cost * 1.01)
          << "goal " << goal_xy.transpose() << " seed " << seed << ": " << r.lost_ants_total << " ants lost";
      EXPECT_GE(r.combined_cost, exact.combined_cost - 1e-9);
    }
  }
}
