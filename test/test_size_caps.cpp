// The size caps of the core: the cells of a grid (kMaxGridCells), the pheromone of a colony's
// region (kMaxPheromoneBytes), and cost rules that would let a move cost less than its length.
// Every refusal is checked on the dimensions, never by allocating the memory refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "eaci/aco/colony_region.hpp"
#include "eaci/planner.hpp"

using eaci::Algorithm;
using eaci::Cell;
using eaci::CellPath;
using eaci::CostGrid;
using eaci::PlanStatus;

namespace {

TEST(SizeCaps, GridCapIsTwoToTheThirtyCells) {
  EXPECT_EQ(eaci::kMaxGridCells, std::size_t{1073741824});
  // 2^30 < 2^32 - 1 (ColonyRegion::kNone) with room for an index plus any move's step.
  EXPECT_LT(eaci::kMaxGridCells + 2 * 32768 + 2, std::size_t{eaci::ColonyRegion::kNone});
}

TEST(SizeCaps, CostGridRefusesMoreCellsThanTheCapBeforeAllocating) {
  // 40000 x 40000 = 1.6 billion cells (1.6 GB had it been made).
  try {
    CostGrid grid(40000, 40000, false);
    FAIL() << "a grid of 40000 x 40000 cells was made";
  } catch (const std::length_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("40000 x 40000"), std::string::npos) << message;
    EXPECT_NE(message.find("1073741824"), std::string::npos) << message;
  }
  EXPECT_THROW(CostGrid(-1, 5, false), std::invalid_argument);
}

TEST(SizeCaps, PlanRefusesAViewLargerThanTheCapWithoutReadingIt) {
  // The view claims 50000 x 30000 cells (1.5 billion) over a buffer of one byte: plan() must
  // refuse it from its size alone.
  const std::uint8_t one_cell = 0;
  const eaci::GridView view(&one_cell, 50000, 30000);
  for (Algorithm algorithm : {Algorithm::kEaci, Algorithm::kAco, Algorithm::kAStar}) {
    const auto r = eaci::plan(view, Cell{0, 0}, Cell{0, 1}, algorithm, eaci::Parameters{});
    EXPECT_EQ(r.status, PlanStatus::kInvalidMap);
    EXPECT_NE(r.error.find("50000 x 30000"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("1073741824"), std::string::npos) << r.error;
  }
}

TEST(SizeCaps, RegionOverItsCellCapIsNotMade) {
  // 100 x 100 open cells, a route down the middle column, margin 10: 100 x 21 = 2100 cells.
  const CostGrid grid(100, 100, false);
  CellPath route;
  for (int row = 0; row < 100; ++row) route.push_back(Cell{row, 50});
  const auto fits = eaci::ColonyRegion::aroundRoute(grid, route, 10, eaci::ColonyRegion{}, 2100);
  EXPECT_FALSE(fits.tooLarge());
  EXPECT_EQ(fits.size(), 2100u);
  const auto over = eaci::ColonyRegion::aroundRoute(grid, route, 10, eaci::ColonyRegion{}, 2099);
  EXPECT_TRUE(over.tooLarge());
  EXPECT_EQ(over.size(), 0u);
}

TEST(SizeCaps, GeodesicRegionCapIsThePheromoneCap) {
  // 2 GiB / 128 bytes a cell = 16 Mi cells.
  EXPECT_EQ(eaci::kMaxPheromoneCells, std::size_t{16} << 20);
}

TEST(SizeCaps, CostRuleThatMakesAMoveCheaperThanItsLengthIsRefused) {
  CostGrid grid(3, 3, false, eaci::CostRule{50.0, 3.0});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const eaci::CostRule& bad : {eaci::CostRule{0.0, 3.0}, eaci::CostRule{-50.0, 3.0}, eaci::CostRule{50.0, -1.0},
                                    eaci::CostRule{nan, 3.0}, eaci::CostRule{50.0, nan}, eaci::CostRule{inf, 3.0},
                                    eaci::CostRule{50.0, inf}, eaci::CostRule{1e-320, 1e6}}) {
    try {
      grid.setCostRule(bad);
      ADD_FAILURE() << "accepted neutral_cost " << bad.neutral_cost << ", cost_factor " << bad.cost_factor;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("at least its length"), std::string::npos) << e.what();
    }
  }
  // The grid keeps its rule: a move into a cell of cost 100 costs 1 x (50 + 3 x 100) / 50 = 7.
  grid.setCost(Cell{1, 1}, 100);
  EXPECT_DOUBLE_EQ(grid.moveCost(Cell{1, 0}, eaci::directionBetween(Cell{1, 0}, Cell{1, 1})), 7.0);
  // cost_factor 0 (plan by length) is a move's length exactly.
  grid.setCostRule(eaci::CostRule{50.0, 0.0});
  EXPECT_DOUBLE_EQ(grid.moveCost(Cell{1, 0}, eaci::directionBetween(Cell{1, 0}, Cell{1, 1})), 1.0);
}

}  // namespace
