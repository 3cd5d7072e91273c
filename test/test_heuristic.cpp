// Eq. 9, 16, 17: heuristic values and the turning cost of every turn.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "eaci/aco/ant_walk.hpp"
#include "eaci/aco/heuristic.hpp"

namespace {
constexpr int kEast = 0, kNorthEast = 1, kNorth = 2, kNorthWest = 3, kSouthEast = 7;
}

TEST(Heuristic, TurningCostIsKTimesEpsilonForKTimes45Degrees) {
  const double eps = 0.5;
  EXPECT_DOUBLE_EQ(eaci::turningCost(kEast, kEast, eps), 0.0);          // 0 degrees
  EXPECT_DOUBLE_EQ(eaci::turningCost(kEast, kNorthEast, eps), 0.5);     // 45
  EXPECT_DOUBLE_EQ(eaci::turningCost(kEast, kSouthEast, eps), 0.5);     // 45 the other way
  EXPECT_DOUBLE_EQ(eaci::turningCost(kEast, kNorth, eps), 1.0);         // 90
  EXPECT_DOUBLE_EQ(eaci::turningCost(kEast, kNorthWest, eps), 1.5);     // 135
  EXPECT_DOUBLE_EQ(eaci::turningCost(kSouthEast, kNorthEast, eps), 1.0);  // 90 across the wrap
  EXPECT_DOUBLE_EQ(eaci::turningCost(kSouthEast, kNorth, 0.3), 0.9);      // 135
}

TEST(Heuristic, FirstMoveOfARouteHasNoTurningCost) {
  EXPECT_DOUBLE_EQ(eaci::turningCost(-1, kNorthWest, 0.5), 0.0);
}

// Hand-computed eta values, read from the walk the solver runs (beta = 1, so the weight is eta).
TEST(Heuristic, EtaValues) {
  const auto grid = eaci::CostGrid::fromRows(std::vector<std::vector<int>>(6, std::vector<int>(6, 0)), false);
  const eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  const eaci::Cell from{0, 0};
  const auto from_cell = static_cast<std::uint32_t>(grid.index(from));  // the whole map: region cell = grid index
  // Target (0, 5): the east move lands on (0, 1), 4 cells from it.
  const eaci::WalkSetup classic(grid, field, {from, eaci::Cell{0, 5}}, eaci::HeuristicRule::kGoalDistance, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(classic.heuristicWeight(from, from_cell, 1, -1, kEast), 0.25);  // Eq. 9: 1 / 4
  const eaci::WalkSetup turning(grid, field, {from, eaci::Cell{0, 5}}, eaci::HeuristicRule::kTurningAware, 1.0, 1.0);
  EXPECT_DOUBLE_EQ(turning.heuristicWeight(from, from_cell, 1, kNorthEast, kEast), 0.2);  // Eq. 16: 1 / (4 + 1)
  EXPECT_DOUBLE_EQ(turning.heuristicWeight(from, from_cell, 1, kEast, kEast), 0.25);      // no turn: 1 / 4
  // Target (0, 3): from (0, 1) it is 2 cells away; straight on, eta = 1 / 2.
  const eaci::WalkSetup near(grid, field, {from, eaci::Cell{0, 3}}, eaci::HeuristicRule::kTurningAware, 1.0, 1.0);
  EXPECT_DOUBLE_EQ(near.heuristicWeight(from, from_cell, 1, -1, kEast), 0.5);
}

TEST(Heuristic, FastInversePowerEqualsPow) {
  for (double beta : {0.0, 1.0, 2.0, 7.0, 12.0, 2.5, 7.3, 13.0}) {
    const eaci::InversePower power(beta);
    for (double x : {0.5, 1.0, 1.7, 12.25, 80.0})
      EXPECT_NEAR(power(x) / std::pow(x, -beta), 1.0, 1e-12) << "beta " << beta << " x " << x;
  }
}

TEST(Heuristic, WalkWeightIsEtaToTheBetaOfEquationSixteen) {
  // The walk's tabulated weight must equal (1 / (d_jg + sigma))^beta computed from the equations.
  const auto grid = eaci::CostGrid::fromRows(std::vector<std::vector<int>>(6, std::vector<int>(6, 0)), false);
  const eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  const eaci::WalkSetup setup(grid, field, {eaci::Cell{0, 0}, eaci::Cell{5, 4}}, eaci::HeuristicRule::kTurningAware,
                              7.0, 0.5);
  const eaci::Cell from{1, 0}, next{2, 1};  // the south-east move
  const auto from_cell = static_cast<std::uint32_t>(grid.index(from));  // the whole map: region cell = grid index
  const double d = std::hypot(5 - 2, 4 - 1);
  for (int previous : {-1, 0, 1, 2, 3, 4, 5, 6, 7}) {
    const int dir = 7;  // south-east
    const int turn_steps = previous < 0 ? 0 : std::min((dir - previous + 8) % 8, (previous - dir + 8) % 8);
    const double expected = std::pow(1.0 / (d + 0.5 * turn_steps), 7.0);  // Eq. 16-17 by hand
    EXPECT_NEAR(setup.heuristicWeight(from, from_cell, 1, previous, dir) / expected, 1.0, 1e-6);
    (void)next;
  }
}
