// Eq. 18-22: non-uniform initial pheromone on a region small enough to work out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "eaci/aco/initial_pheromone.hpp"

using eaci::ColonyRegion;
using eaci::CostGrid;
using eaci::Cell;

namespace {
constexpr int kEast = 0, kNorthEast = 1, kNorth = 2, kSouthEast = 7, kWest = 4;
}

TEST(InitialPheromone, LineThroughTwoCentres) {
  const auto line = eaci::Line::through({0.5, 0.5}, {2.5, 2.5});  // y = x
  EXPECT_NEAR(line.distanceTo({1.0, 0.5}), 0.5 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(line.distanceTo({3.0, 3.0}), 0.0, 1e-12);
}

TEST(InitialPheromone, HandComputedRegion) {
  // 3 rows x 4 columns, islands (2,0) -> (0,2): centres (0.5,0.5) and (2.5,2.5), the line y = x.
  // The region is columns 0-2; column 3 lies outside.
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}}, true);
  const double lambda = 3.0;
  const auto field = eaci::initialIslandPheromone(grid, ColonyRegion::wholeMap(grid), {Cell{2, 0}, Cell{0, 2}}, lambda, 1.0);
  const double sqrt2 = std::sqrt(2.0);
  const double max_tau0 = 2.0 * sqrt2;   // midpoints 0.5/sqrt2 from the line
  const double min_tau0 = sqrt2 / 1.5;   // midpoints 1.5/sqrt2 from the line
  auto tau = [&](Cell c, int d) { return field.tau(grid.index(c), d); };
  // Eq. 18: (2,0) -> (2,1), midpoint (1, 0.5).
  EXPECT_NEAR(tau(Cell{2, 0}, kEast), max_tau0, 1e-12);
  // Eq. 18: (2,1) -> (1,2), midpoint (2, 1): 1/sqrt2 away.
  EXPECT_NEAR(tau(Cell{2, 1}, kNorthEast), sqrt2, 1e-12);
  // Eq. 20: (1,0) -> (2,1), midpoint (1,1) on the line; node (0.5, 1.5) is 1/sqrt2 away.
  EXPECT_NEAR(tau(Cell{1, 0}, kSouthEast), sqrt2, 1e-12);
  // Eq. 20-21: (2,0) -> (1,1): midpoint and node on the line -> +inf -> lambda * max tau0.
  EXPECT_NEAR(tau(Cell{2, 0}, kNorthEast), lambda * max_tau0, 1e-12);
  EXPECT_NEAR(tau(Cell{1, 1}, kNorthEast), lambda * max_tau0, 1e-12);
  // (0,0) -> (1,0) in the corner: midpoint (0.5, 2) is 1.5/sqrt2 away: the minimum.
  EXPECT_NEAR(tau(Cell{0, 0}, 6), min_tau0, 1e-12);
  // Eq. 22: edges leaving or outside the region take min tau0.
  EXPECT_NEAR(tau(Cell{0, 2}, kEast), min_tau0, 1e-12);
  EXPECT_NEAR(tau(Cell{0, 3}, kWest), min_tau0, 1e-12);
  EXPECT_NEAR(tau(Cell{2, 3}, kNorth), min_tau0, 1e-12);
}

TEST(InitialPheromone, EdgeInTwoRegionsTakesTheLargerValue) {
  // 2 x 4 map, islands (1,3) -> (0,2) -> (1,0). Both regions hold column 2, so the edge
  // (1,2) -> (0,2) is in both. Region 1 (cols 2-3): line x + y - 4 = 0, midpoint (2.5, 1)
  // is 0.5/sqrt2 away -> 2 sqrt2. Region 2 (cols 0-2): line x - 2y + 0.5 = 0, 1/sqrt5 away
  // -> sqrt5. The larger, 2 sqrt2, must win although region 2 comes last.
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0, 0}, {0, 0, 0, 0}}, true);
  const auto field = eaci::initialIslandPheromone(grid, ColonyRegion::wholeMap(grid), {Cell{1, 3}, Cell{0, 2}, Cell{1, 0}}, 3.0, 1.0);
  EXPECT_NEAR(field.tau(grid.index(Cell{1, 2}), kNorth), 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(field.tau(grid.index(Cell{0, 2}), 6), 2.0 * std::sqrt(2.0), 1e-12);
}

TEST(InitialPheromone, WeightsAreTauToTheAlpha) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, true);
  const auto field = eaci::initialIslandPheromone(grid, ColonyRegion::wholeMap(grid), {Cell{2, 0}, Cell{0, 2}}, 3.0, 1.1);
  const std::size_t i = grid.index(Cell{2, 0});
  EXPECT_NEAR(field.weight(i, kEast), std::pow(2.0 * std::sqrt(2.0), 1.1), 1e-12);
}
