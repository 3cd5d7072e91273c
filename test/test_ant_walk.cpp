// One ant's walk: the move rule, the taboo list, islands in order, lost ants.
#include <gtest/gtest.h>

#include "eaci/aco/ant_walk.hpp"
#include "test_support.hpp"

using eaci::AntRoute;
using eaci::CostGrid;
using eaci::Cell;

namespace {
eaci::CellPath cellsOf(const CostGrid& grid, const AntRoute& route) {
  eaci::CellPath path;
  for (auto index : route.cells) path.push_back(grid.cellAt(index));
  return path;
}
}  // namespace

TEST(AntWalk, DeadEndWithoutAWayBackIsALostAnt) {
  // S at the mouth of a one-cell-wide dead end whose only exit is S itself: the ant must
  // enter it (E is walled off from that side... here E is reachable only through S).
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0, 0}, {1, 1, 1, 0}, {0, 0, 0, 0}}, false);
  const eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  // From (0,1) heading to (2,0): going west into (0,0) is a trap (nothing beyond it).
  const eaci::WalkSetup setup(grid, field, {Cell{0, 1}, Cell{2, 0}}, eaci::HeuristicRule::kGoalDistance, 7.0, 0.5);
  eaci::AntWalker walker;
  int lost = 0, arrived = 0;
  for (int k = 0; k < 200; ++k) {
    eaci::SplitMix64 rng = eaci::antStream(1, 1, static_cast<std::uint64_t>(k));
    AntRoute route;
    walker.walk(setup, rng, route);
    if (!route.complete) {
      ++lost;
      EXPECT_EQ(cellsOf(grid, route).back(), (Cell{0, 0}));  // lost exactly in the trap
    } else {
      ++arrived;
      EXPECT_EQ(eaci::test::routeDefect(grid, cellsOf(grid, route), Cell{0, 1}, Cell{2, 0}), "");
      EXPECT_NEAR(route.length, 7.0, 1e-12);  // (0,1) -> (0,3) -> (2,3) -> (2,0): seven straight steps
    }
  }
  EXPECT_GT(lost, 0);
  EXPECT_GT(arrived, 0);
  EXPECT_EQ(lost + arrived, 200);
}

TEST(AntWalk, VisitsIslandsInOrderAndNeverAnotherIslandEarly) {
  // Open 5 x 5 map; waypoints zig-zag so that the straight way to the second one passes
  // over the third. The third may only be entered after the second.
  const CostGrid grid = CostGrid::fromRows(std::vector<std::vector<int>>(5, std::vector<int>(5, 0)), false);
  const eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  const std::vector<Cell> islands{{2, 0}, {2, 4}, {2, 2}, {0, 2}};
  const eaci::WalkSetup setup(grid, field, islands, eaci::HeuristicRule::kTurningAware, 7.0, 0.5);
  eaci::AntWalker walker;
  for (int k = 0; k < 100; ++k) {
    eaci::SplitMix64 rng = eaci::antStream(3, 1, static_cast<std::uint64_t>(k));
    AntRoute route;
    walker.walk(setup, rng, route);
    if (!route.complete) continue;
    const auto path = cellsOf(grid, route);
    EXPECT_EQ(eaci::test::routeDefect(grid, path, islands.front(), islands.back()), "");
    std::size_t next = 1;
    for (const Cell& c : path) {
      for (std::size_t w = next + 1; w < islands.size(); ++w) EXPECT_NE(c, islands[w]) << "island " << w << " early";
      if (next < islands.size() && c == islands[next]) ++next;
    }
    EXPECT_EQ(next, islands.size());
  }
}

TEST(AntWalk, TakesTheGoalAtOnceWhenItIsANeighbour) {
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, false);
  eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  // Make every other move from the start overwhelmingly attractive.
  for (int d = 0; d < eaci::kDirections; ++d) field.set(grid.index(Cell{1, 1}), d, 1e6);
  field.set(grid.index(Cell{1, 1}), 0, 1e-9);  // east, to the goal (1,2)
  field.refreshWeights();
  const eaci::WalkSetup setup(grid, field, {Cell{1, 1}, Cell{1, 2}}, eaci::HeuristicRule::kGoalDistance, 1.0, 0.5);
  eaci::AntWalker walker;
  eaci::SplitMix64 rng(5);
  AntRoute route;
  walker.walk(setup, rng, route);
  ASSERT_TRUE(route.complete);
  EXPECT_EQ(route.cells.size(), 2u);
}

TEST(AntWalk, RouletteFollowsTheProbabilitiesOfEquationEight) {
  // r0: 1 0 0 0     S = (1,1), E = (0,3). With beta = 0 the heuristic drops out and the
  // r1: 0 0 0 1     first move follows tau alone: north 3, north-east 1, west and east ~0
  //                 -> P(north) = 3/4, P(north-east) = 1/4.
  const CostGrid grid = CostGrid::fromRows({{1, 0, 0, 0}, {0, 0, 0, 1}}, false);
  eaci::PheromoneField field(grid.cellCount(), 1.0, 1.0);
  const std::size_t s = grid.index(Cell{1, 1});
  field.set(s, 2, 3.0);    // north
  field.set(s, 1, 1.0);    // north-east
  field.set(s, 4, 1e-12);  // west
  field.set(s, 0, 1e-12);  // east
  field.refreshWeights();
  const eaci::WalkSetup setup(grid, field, {Cell{1, 1}, Cell{0, 3}}, eaci::HeuristicRule::kGoalDistance, 0.0, 0.5);
  eaci::AntWalker walker;
  const int walks = 4000;
  int north = 0, north_east = 0;
  for (int k = 0; k < walks; ++k) {
    eaci::SplitMix64 rng = eaci::antStream(11, 1, static_cast<std::uint64_t>(k));
    AntRoute route;
    walker.walk(setup, rng, route);
    ASSERT_FALSE(route.dirs.empty());
    north += route.dirs.front() == 2;
    north_east += route.dirs.front() == 1;
  }
  EXPECT_NEAR(static_cast<double>(north) / walks, 0.75, 0.025);      // 3.7 standard deviations
  EXPECT_NEAR(static_cast<double>(north_east) / walks, 0.25, 0.025);
}
