// Eq. 10-11 and Eq. 23-25: one update step, worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "eaci/aco/pheromone_update.hpp"
#include "eaci/grid/cost_grid.hpp"

using eaci::AntRoute;
using eaci::CostGrid;
using eaci::Cell;

namespace {
constexpr int kEast = 0, kNorthEast = 1, kSouthEast = 7;

// 2 x 3 map, S = (0,0), E = (0,2), d_SE = 2. Route A: east, east (length 2).
// Route B: south-east, north-east (length 2 sqrt2). Route C: a lost ant.
struct Fixture {
  CostGrid grid = CostGrid::fromRows({{0, 0, 0}, {0, 0, 0}}, true);
  std::vector<AntRoute> routes;
  Fixture() {
    AntRoute a;
    a.reset(static_cast<std::uint32_t>(grid.index(Cell{0, 0})));
    a.cells = {0, 1, 2};
    a.dirs = {kEast, kEast};
    a.length = a.cost = 2.0;  // a binary map: L_k, the cost, is the length
    a.complete = true;
    AntRoute b;
    b.reset(0);
    b.cells = {0, 4, 2};
    b.dirs = {kSouthEast, kNorthEast};
    b.length = b.cost = 2.0 * std::sqrt(2.0);
    b.complete = true;
    AntRoute c;
    c.reset(0);
    c.cells = {0, 3};
    c.dirs = {6};
    c.length = c.cost = 1.0;
    c.complete = false;
    routes = {a, b, c};
  }
};
}  // namespace

TEST(PheromoneUpdate, AdaptiveEvaporationRate) {
  EXPECT_DOUBLE_EQ(eaci::adaptiveEvaporationRate(0.9, 2.0, 2.0), 0.9);   // Eq. 25
  EXPECT_DOUBLE_EQ(eaci::adaptiveEvaporationRate(0.9, 30.0, 60.0), 0.45);
  EXPECT_DOUBLE_EQ(eaci::adaptiveEvaporationRate(1.3, 2.0, 2.0), 1.0);   // capped
}

TEST(PheromoneUpdate, AdaptiveStepRewardsBestAndPunishesWorst) {
  Fixture f;
  eaci::PheromoneField field(f.grid.cellCount(), 1.0, 1.0);
  eaci::adaptivePheromoneUpdate(field, f.routes, /*best=*/0, /*worst=*/1, 0.9, 100.0, 2.0);
  const double rho = 0.9;                                          // 0.9 * 2 / 2
  const double reward = 0.9 * 100.0 * 2.0 / (2.0 * 2.0);           // 45
  const double penalty = 0.9 * 100.0 * 2.0 / (2.0 * std::sqrt(8.0));  // 31.8198
  // Route A's edges: evaporated 1, its own deposit Q/2, plus rho * reward.
  EXPECT_NEAR(field.tau(0, kEast), 0.1 + 50.0 + rho * reward, 1e-9);
  EXPECT_NEAR(field.tau(1, kEast), 90.6, 1e-9);
  // Route B's edges: deposit Q / (2 sqrt2) minus rho * penalty.
  EXPECT_NEAR(field.tau(0, kSouthEast), 0.1 + 100.0 / std::sqrt(8.0) - rho * penalty, 1e-9);
  EXPECT_NEAR(field.tau(4, kNorthEast), 6.81751, 1e-5);
  // The lost ant deposits nothing; untouched edges only evaporate.
  EXPECT_NEAR(field.tau(0, 6), 0.1, 1e-12);
  EXPECT_NEAR(field.tau(5, kEast), 0.1, 1e-12);
  EXPECT_NEAR(field.weight(0, kEast), 90.6, 1e-9);  // alpha = 1: weights follow tau
}

TEST(PheromoneUpdate, PenaltyNeverDrivesPheromoneToZero) {
  Fixture f;
  eaci::PheromoneField field(f.grid.cellCount(), 1e-6, 1.0);
  f.routes[1].complete = false;
  f.routes[0].length = f.routes[0].cost = 2.0;
  // Best and worst the same route: reward and penalty cancel, tau stays positive everywhere.
  eaci::adaptivePheromoneUpdate(field, f.routes, 0, 0, 1.3, 100.0, 2.0);
  for (std::size_t cell = 0; cell < f.grid.cellCount(); ++cell)
    for (int d = 0; d < eaci::kDirections; ++d) EXPECT_GT(field.tau(cell, d), 0.0);
  EXPECT_NEAR(field.tau(0, kEast), 50.0, 1e-9);  // rho = 1: old pheromone gone, Q/L remains
}

TEST(PheromoneUpdate, IterationWithoutARouteLeavesTheFieldAlone) {
  Fixture f;
  eaci::PheromoneField field(f.grid.cellCount(), 2.0, 1.0);
  eaci::adaptivePheromoneUpdate(field, f.routes, -1, -1, 0.9, 100.0, 2.0);
  EXPECT_DOUBLE_EQ(field.tau(0, kEast), 2.0);
}

TEST(PheromoneUpdate, ClassicStepEvaporatesAndDeposits) {
  Fixture f;
  eaci::PheromoneField field(f.grid.cellCount(), 1.0, 1.1);
  eaci::classicPheromoneUpdate(field, f.routes, 0.3, 100.0);  // Eq. 10-11
  EXPECT_NEAR(field.tau(0, kEast), 0.7 + 50.0, 1e-9);
  EXPECT_NEAR(field.tau(0, kSouthEast), 0.7 + 100.0 / std::sqrt(8.0), 1e-9);
  EXPECT_NEAR(field.tau(0, 6), 0.7, 1e-12);
  EXPECT_NEAR(field.weight(0, kEast), std::pow(50.7, 1.1), 1e-9);
}
