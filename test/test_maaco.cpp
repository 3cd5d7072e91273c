// MAACO (re-implemented from public descriptions, not the authors' code): each rule against
// numbers worked out by hand from its formula (docs/algorithm.md, MAACO), the parameter
// checks, and the colony on the paper's maps against bounds that follow from its rules.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "eaci/aco/candidate_moves.hpp"
#include "eaci/aco/elliptical_pheromone.hpp"
#include "eaci/aco/maaco_heuristic.hpp"
#include "eaci/aco/pheromone_update.hpp"
#include "eaci/aco/transition.hpp"
#include "eaci/planner.hpp"
#include "test_support.hpp"

using eaci::Cell;

namespace {

eaci::CostGrid openGrid(int rows, int cols) {
  eaci::OccupancyMap map;
  map.width = cols;
  map.height = rows;
  map.cells.assign(static_cast<std::size_t>(rows * cols), 0);
  return eaci::CostGrid::fromView(map.view(), true);
}

constexpr unsigned bit(int d) { return 1u << d; }
// Directions (moves.hpp): 0 east, 1 north-east, 2 north, 3 north-west, 4 west, 5 south-west,
// 6 south, 7 south-east; row grows southwards.
constexpr int kEast = 0, kNorthEast = 1, kNorth = 2, kNorthWest = 3, kWest = 4, kSouthWest = 5, kSouth = 6,
              kSouthEast = 7;

}  // namespace

// tau(i -> j) = C d_ST / (d_Sj + d_jT): S (0,0), T (0,4), C = 2. Into (1,2): d_Sj = d_jT = sqrt 5,
// so 2 * 4 / (2 sqrt 5) = 4 / sqrt 5; into (0,2), on the segment: C = 2; into (4,4): d_Sj =
// sqrt 32, d_jT = 4, so 8 / (sqrt 32 + 4).
TEST(MaacoInitialPheromone, IsTheEllipticalFormulaOfTheCellTheMoveEnters) {
  const eaci::CostGrid grid = openGrid(5, 5);
  const eaci::ColonyRegion region = eaci::ColonyRegion::wholeMap(grid);
  const eaci::PheromoneField field =
      eaci::ellipticalInitialPheromone(grid, region, Cell{0, 0}, Cell{0, 4}, 2.0, 1.0);
  const auto at = [&](Cell from, int dir) { return field.tau(region.regionIndex(from), dir); };
  EXPECT_NEAR(at(Cell{0, 2}, kSouth), 4.0 / std::sqrt(5.0), 1e-12);      // into (1,2)
  EXPECT_NEAR(at(Cell{1, 1}, kEast), 4.0 / std::sqrt(5.0), 1e-12);       // into (1,2) too
  EXPECT_NEAR(at(Cell{1, 2}, kNorth), 2.0, 1e-12);                       // into (0,2)
  EXPECT_NEAR(at(Cell{3, 3}, kSouthEast), 8.0 / (std::sqrt(32.0) + 4.0), 1e-12);  // into (4,4)
  EXPECT_NEAR(at(Cell{0, 3}, kEast), 2.0, 1e-12);                        // into T
}

// q0 (K - k) / K before k0 = 0.7 K; from k0 on q0_k0 + (k - k0) / (K - k0) (q0 - q0_k0) / 2.
// K = 100, q0 = 0.5: q0_k0 = 0.15, and at K 0.15 + 0.35 / 2 = 0.325.
TEST(MaacoTransition, QZeroScheduleByHand) {
  EXPECT_NEAR(eaci::exploitationProbability(1, 100, 0.5), 0.495, 1e-12);
  EXPECT_NEAR(eaci::exploitationProbability(50, 100, 0.5), 0.25, 1e-12);
  EXPECT_NEAR(eaci::exploitationProbability(69, 100, 0.5), 0.155, 1e-12);
  EXPECT_NEAR(eaci::exploitationProbability(70, 100, 0.5), 0.15, 1e-12);
  EXPECT_NEAR(eaci::exploitationProbability(85, 100, 0.5), 0.2375, 1e-12);
  EXPECT_NEAR(eaci::exploitationProbability(100, 100, 0.5), 0.325, 1e-12);
  // K = 10: k0 = 7.
  EXPECT_NEAR(eaci::exploitationProbability(6, 10, 0.5), 0.2, 1e-12);
  EXPECT_NEAR(eaci::exploitationProbability(10, 10, 0.5), 0.325, 1e-12);
}

TEST(MaacoTransition, QZeroOneTakesTheHeaviestCandidate) {
  const double weights[] = {0.2, 0.5, 0.5, 0.1};
  eaci::PseudoRandomTransition greedy{1.0, 1.0};
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    eaci::SplitMix64 rng(seed);
    EXPECT_EQ(greedy(weights, 4, 1.3, rng), 1);  // the first of the two heaviest
  }
}

// h = wh_max - (wh_max - wh_min) exp(-k d_jT / d_ST), g = 1 - h, 1 / eta = g d_sj + h d_jT + a c.
// wh 0.9 / 0.2, k 1, d_ST 10, d_jT 5: h = 0.9 - 0.7 e^-0.5 = 0.4754285382, g = 0.5245714618;
// d_sj 6 with a turn (a = 1): 3.1474287708 + 2.3771426910 + 1 = 6.5245714618.
TEST(MaacoHeuristic, WeightsByHand) {
  EXPECT_NEAR(eaci::goalDistanceWeight(5.0, 10.0, 0.9, 0.2, 1.0), 0.4754285382, 1e-10);
  EXPECT_NEAR(eaci::goalDistanceWeight(0.0, 10.0, 0.9, 0.2, 1.0), 0.2, 1e-12);  // at the goal: wh_min
  const eaci::MaacoHeuristicWeights w{0.9, 0.2, 1.0, 1.0};
  EXPECT_NEAR(eaci::maacoHeuristicDistance(6.0, 5.0, 10.0, true, w), 6.5245714618, 1e-9);
  EXPECT_NEAR(eaci::maacoHeuristicDistance(6.0, 5.0, 10.0, false, w), 5.5245714618, 1e-9);
}

// The walk's rule: S (0,0), T (0,10) (d_ST 10); from (1,4) after 4.5 cells walked, eastward
// into (1,5): d_jT = sqrt 26, d_sj = 4.5 + 1 (walked) or sqrt 26 (straight), no turn after an
// eastward move, a turn after a north-eastward one.
TEST(MaacoHeuristic, TheWalkRuleReadsTheRouteAndTheTurn) {
  const eaci::MaacoHeuristicWeights w{0.9, 0.2, 1.0, 1.0};
  const double d_jt = std::sqrt(26.0);
  const double h = 0.9 - 0.7 * std::exp(-d_jt / 10.0);
  const eaci::MaacoHeuristic walked(w, false, Cell{0, 0}, Cell{0, 10});
  const eaci::MaacoHeuristic straight(w, true, Cell{0, 0}, Cell{0, 10});
  const int no_setup = 0;
  EXPECT_NEAR(walked(no_setup, 4.5, Cell{1, 4}, 0, 1, kEast, kEast), (1 - h) * 5.5 + h * d_jt, 1e-12);
  EXPECT_NEAR(walked(no_setup, 4.5, Cell{1, 4}, 0, 1, kNorthEast, kEast), (1 - h) * 5.5 + h * d_jt + 1.0, 1e-12);
  EXPECT_NEAR(walked(no_setup, 0.0, Cell{1, 4}, 0, 1, -1, kEast), (1 - h) * 1.0 + h * d_jt, 1e-12);  // first move
  EXPECT_NEAR(straight(no_setup, 4.5, Cell{1, 4}, 0, 1, kEast, kEast), (1 - h) * d_jt + h * d_jt, 1e-12);
}

// Quadrant: S (0,0) -> T (5,5) allows east, south, south-east; none open: the same against
// here -> T; none open either: every open move.
TEST(MaacoCandidates, QuadrantFilterAndItsFallbacks) {
  const eaci::GoalDirectionMoves quadrant(false, Cell{0, 0}, Cell{5, 5});
  const unsigned all = 0xFFu;
  EXPECT_EQ(quadrant(all, Cell{2, 2}), bit(kEast) | bit(kSouth) | bit(kSouthEast));
  // Past T (at (7,7)) with only the moves back open: here -> T allows west, north, north-west.
  const unsigned back = bit(kNorth) | bit(kNorthWest) | bit(kWest) | bit(kNorthEast);
  EXPECT_EQ(quadrant(back, Cell{7, 7}), bit(kNorth) | bit(kNorthWest) | bit(kWest));
  // Neither: every open move.
  EXPECT_EQ(quadrant(bit(kNorthEast) | bit(kSouthWest), Cell{2, 2}), bit(kNorthEast) | bit(kSouthWest));
  EXPECT_EQ(quadrant(0u, Cell{2, 2}), 0u);  // nothing open: a lost ant
}

// Nearest three in angle to here -> T (south-east): south-east, then east and south; with
// south-east taken, east, south and the first of the 90-degree ones, north-east.
TEST(MaacoCandidates, NearestThreeInAngle) {
  const eaci::GoalDirectionMoves nearest(true, Cell{0, 0}, Cell{5, 5});
  EXPECT_EQ(nearest(0xFFu, Cell{2, 2}), bit(kSouthEast) | bit(kEast) | bit(kSouth));
  EXPECT_EQ(nearest(0xFFu & ~bit(kSouthEast), Cell{2, 2}), bit(kEast) | bit(kSouth) | bit(kNorthEast));
  EXPECT_EQ(nearest(bit(kWest), Cell{2, 2}), bit(kWest));
}

// Wide: tau_max = 200 (1 / (2 (1 - rho)) + 1) / L = 200 * 1.625 / 50 = 6.5, tau_min = 0.013;
// tight: 1 / ((1 - rho) L) = 0.025, tau_min = 0.025 / (2 * 40) = 0.0003125.
TEST(MaacoPheromone, BoundsByHand) {
  const eaci::PheromoneBounds wide = eaci::maacoPheromoneBounds(eaci::MaacoBounds::kWide, 0.2, 50.0, 40);
  EXPECT_NEAR(wide.max, 6.5, 1e-12);
  EXPECT_NEAR(wide.min, 0.013, 1e-12);
  const eaci::PheromoneBounds tight = eaci::maacoPheromoneBounds(eaci::MaacoBounds::kTight, 0.2, 50.0, 40);
  EXPECT_NEAR(tight.max, 0.025, 1e-12);
  EXPECT_NEAR(tight.min, 0.0003125, 1e-12);
}

// After the update every edge lies within the bounds: tau0 = 10 above tau_max falls to it; an
// edge far below tau_min rises to it.
TEST(MaacoPheromone, TheUpdateKeepsEveryEdgeWithinTheBounds) {
  eaci::PheromoneField field(4, 10.0, 1.0);
  field.set(2, 3, 1e-6);
  field.refreshChanged();
  std::vector<eaci::AntRoute> routes(1);
  routes[0].reset(0);
  routes[0].cells.push_back(1);
  routes[0].dirs.push_back(kEast);
  routes[0].cost = routes[0].length = 1.0;
  routes[0].complete = true;
  const eaci::BoundedUpdate update{0.2, 2.5, eaci::MaacoBounds::kWide, 2};
  update(field, routes, 0, 0, 50.0);
  EXPECT_NEAR(field.tau(1, kWest), 6.5, 1e-9);
  EXPECT_NEAR(field.tau(0, kEast), 6.5, 1e-9);  // 8 + 2.5 is above the bound too
  EXPECT_NEAR(field.tau(2, 3), 0.013, 1e-12);
  EXPECT_NEAR(field.weight(2, 3), 0.013, 1e-12);  // alpha 1: the weight follows
}

TEST(MaacoParameters, DefaultsAreThePublicRecords) {
  const eaci::Parameters p;
  EXPECT_EQ(p.maaco_alpha, 1.0);
  EXPECT_EQ(p.beta, 7.0);
  EXPECT_EQ(p.ants, 50);
  EXPECT_EQ(p.maaco_q, 2.5);
  EXPECT_EQ(p.maaco_q0, 0.5);
  EXPECT_EQ(p.maaco_turn_weight, 1.0);
  EXPECT_EQ(p.maaco_wh_max, 0.9);
  EXPECT_EQ(p.maaco_wh_min, 0.2);
  EXPECT_EQ(eaci::validationError(p), "");
}

TEST(MaacoParameters, BadValuesGetClearErrors) {
  const auto error = [](const std::string& key, const std::string& value) {
    eaci::Parameters p;
    eaci::setParameter(p, key, value);
    return eaci::validationError(p);
  };
  EXPECT_EQ(error("maaco_rho", "nan"), "maaco_rho must be in (0, 1): the pheromone bounds divide by 1 - rho (got nan)");
  EXPECT_EQ(error("maaco_rho", "1"), "maaco_rho must be in (0, 1): the pheromone bounds divide by 1 - rho (got 1)");
  EXPECT_EQ(error("maaco_q", "-2.5"), "maaco_q must be a positive number (got -2.5)");
  EXPECT_EQ(error("maaco_tau0", "0"), "maaco_tau0 must be a positive number (got 0)");
  EXPECT_EQ(error("maaco_q0", "1.5"), "maaco_q0 must be in [0, 1] (got 1.5)");
  EXPECT_EQ(error("maaco_alpha", "-1"), "maaco_alpha must be a number in [0, 20] (got -1)");
  EXPECT_EQ(error("maaco_turn_weight", "-0.1"), "maaco_turn_weight must be a number >= 0 (got -0.1)");
  EXPECT_EQ(error("maaco_wh_max", "1.2"), "maaco_wh_max must be in [0, 1] (got 1.2)");
  EXPECT_EQ(error("maaco_wh_min", "0.95"), "maaco_wh_min must be in [0, maaco_wh_max] (got 0.95)");
  EXPECT_EQ(error("maaco_k_h", "inf"), "maaco_k_h must be a number >= 0 (got inf)");
  eaci::Parameters p;
  try {
    eaci::setParameter(p, "maaco_candidates", "all");
    FAIL() << "no error";
  } catch (const eaci::ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), "maaco_candidates: 'all' is not one of: quadrant, nearest3");
  }
  EXPECT_THROW(eaci::setParameter(p, "maaco_bounds", "loose"), eaci::ParameterError);
  EXPECT_THROW(eaci::setParameter(p, "maaco_start_distance", "manhattan"), eaci::ParameterError);
  const eaci::PlanResult r = eaci::plan(openGrid(3, 3), Cell{0, 0}, Cell{2, 2}, eaci::Algorithm::kMaaco, [] {
    eaci::Parameters bad;
    bad.maaco_rho = -0.1;
    return bad;
  }());
  EXPECT_EQ(r.status, eaci::PlanStatus::kInvalidParameters);
}

// On the paper's maps, seeds 1-20: every route valid and no shorter than the A* optimum; the
// best so far never rises and is the cheapest iteration best; iterations_to_converge is the
// first iteration that reached it; every ant of every iteration walked (no stop_gap: MAACO
// knows no cheapest cost) and at most all of them are lost.
TEST(PaperMaps, MaacoRoutesAreValidAndTheRecordsFollowItsRules) {
  for (const eaci::test::PaperCase& pc : eaci::test::paperCases()) {
    const eaci::CostGrid grid = eaci::test::paperMap(pc.file, true);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      eaci::Parameters p;
      p.allow_corner_cutting = true;
      p.seed = seed;
      p.max_iterations = 30;
      const eaci::PlanResult r = eaci::plan(grid, pc.start, pc.goal, eaci::Algorithm::kMaaco, p);
      ASSERT_TRUE(r.success()) << pc.file << " seed " << seed << ": " << r.error;
      EXPECT_EQ(eaci::test::routeDefect(grid, r.path, pc.start, pc.goal), "") << pc.file << " seed " << seed;
      EXPECT_GE(r.length, pc.optimum_cutting - 1e-4) << pc.file << " seed " << seed;
      EXPECT_NEAR(r.length, eaci::test::countedLength(r.path), 1e-9);
      ASSERT_EQ(r.iterations_run, 30);
      double cheapest = std::numeric_limits<double>::infinity();
      int first = 0;
      for (int k = 0; k < 30; ++k) {
        EXPECT_EQ(r.ants_per_iteration[k], 50);
        EXPECT_LE(r.lost_ants_per_iteration[k], 50);
        if (r.iteration_best_cost[k] < cheapest - 1e-9) {
          cheapest = r.iteration_best_cost[k];
          first = k + 1;
        }
        EXPECT_EQ(r.best_cost_so_far[k], cheapest);
      }
      EXPECT_NEAR(r.cost, cheapest, 1e-9) << pc.file << " seed " << seed;
      EXPECT_EQ(r.iterations_to_converge, first);
    }
  }
}

// The ants of an iteration read the same pheromone and each has its own random stream, so a
// seed gives the same MAACO run on one thread and on two (50 x 50: above kCellsForWorkers).
TEST(PlannerDeterminism, MaacoIsTheSameOnOneAndTwoThreads) {
  const eaci::test::PaperCase& pc = eaci::test::paperCases().back();
  const eaci::CostGrid grid = eaci::test::paperMap(pc.file, true);
  eaci::Parameters p;
  p.allow_corner_cutting = true;
  p.max_iterations = 15;
  p.seed = 7;
  p.threads = 1;
  const eaci::PlanResult one = eaci::plan(grid, pc.start, pc.goal, eaci::Algorithm::kMaaco, p);
  p.threads = 2;
  const eaci::PlanResult two = eaci::plan(grid, pc.start, pc.goal, eaci::Algorithm::kMaaco, p);
  ASSERT_TRUE(one.success());
  EXPECT_EQ(one.path, two.path);
  EXPECT_EQ(one.lost_ants_per_iteration, two.lost_ants_per_iteration);
  EXPECT_EQ(one.iteration_best_cost, two.iteration_best_cost);
}
