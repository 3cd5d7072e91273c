// costmap_2d's inflation on the core's grids (include/eaci/grid/inflation.hpp); expected costs
// worked out by hand from (253 - 1) * exp(-cost_scaling_factor * (d - inscribed_radius)).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/inflation.hpp"

namespace {

eaci::InflationParameters sampleParameters() {
  eaci::InflationParameters p;
  p.inflation_radius = 0.3;
  p.inscribed_radius = 0.1;
  p.cost_scaling_factor = 10.0;
  return p;
}

TEST(Inflation, CostAtGivenDistances) {
  const auto p = sampleParameters();
  EXPECT_EQ(eaci::inflationCost(0.0, p), 254);
  EXPECT_EQ(eaci::inflationCost(0.05, p), 253);
  EXPECT_EQ(eaci::inflationCost(0.1, p), 253);                  // on the inscribed radius
  EXPECT_EQ(eaci::inflationCost(0.1 * std::sqrt(2.0), p), 166);  // 252 e^-0.41421 = 166.54
  EXPECT_EQ(eaci::inflationCost(0.2, p), 92);                   // 252 e^-1 = 92.71
  EXPECT_EQ(eaci::inflationCost(0.3, p), 34);                   // on the inflation radius: 252 e^-2 = 34.10
  EXPECT_EQ(eaci::inflationCost(0.30001, p), 0);                // beyond it
  auto flat = p;
  flat.cost_scaling_factor = 0.0;
  EXPECT_EQ(eaci::inflationCost(0.25, flat), 252);
}

// A 9 x 9 map of 0.1 m cells with one obstacle at (4,4) and an unknown cell at (0,0).
TEST(Inflation, InflatedCostsAroundOneObstacle) {
  std::vector<std::uint8_t> cells(81, 0);
  cells[4 * 9 + 4] = 100;
  cells[0] = 255;
  eaci::CellInterpretation map_file;
  map_file.lethal_cost = 100;
  const eaci::GridView view(cells.data(), 9, 9, eaci::RowOrder::kTopFirst, map_file);
  const std::vector<std::uint8_t> costs = eaci::inflatedCosts(view, 0.1, sampleParameters());
  ASSERT_EQ(costs.size(), 81u);
  const auto cost = [&](int r, int c) { return int(costs[static_cast<std::size_t>(r * 9 + c)]); };
  EXPECT_EQ(cost(4, 4), 254);  // the obstacle
  EXPECT_EQ(cost(4, 5), 253);  // 0.1 m: inscribed
  EXPECT_EQ(cost(3, 4), 253);
  EXPECT_EQ(cost(5, 5), 166);  // 0.1414 m
  EXPECT_EQ(cost(4, 6), 92);   // 0.2 m
  EXPECT_EQ(cost(5, 6), 73);   // 0.2236 m: 252 e^-1.2361 = 73.21
  EXPECT_EQ(cost(6, 6), 40);   // 0.2828 m: 252 e^-1.8284 = 40.49
  EXPECT_EQ(cost(4, 7), 34);   // 0.3 m (3 x 0.1 = 0.30000000000000004) still inflated
  EXPECT_EQ(cost(4, 8), 0);    // 0.4 m
  EXPECT_EQ(cost(5, 7), 0);    // 0.3162 m
  EXPECT_EQ(cost(0, 0), 255);  // unknown kept

  // Read as costmap_2d's char map: 253 and 254 are obstacles, the gradient weighs moves.
  const eaci::GridView inflated(costs.data(), 9, 9, eaci::RowOrder::kTopFirst, eaci::inflatedCostsInterpretation(false));
  const eaci::CostGrid grid = eaci::CostGrid::fromView(inflated, false);
  EXPECT_TRUE(grid.isBlocked({4, 4}));
  EXPECT_TRUE(grid.isBlocked({4, 5}));
  EXPECT_TRUE(grid.isBlocked({0, 0}));
  EXPECT_FALSE(grid.isBlocked({5, 5}));
  EXPECT_EQ(grid.cost({5, 5}), 166);
  EXPECT_TRUE(eaci::CostGrid::fromView(
                  eaci::GridView(costs.data(), 9, 9, eaci::RowOrder::kTopFirst, eaci::inflatedCostsInterpretation(true)), false)
                  .isFree({0, 0}));
}

TEST(Inflation, NoObstacleNoCost) {
  const std::vector<std::uint8_t> cells(6, 0);
  const eaci::GridView view(cells.data(), 3, 2);
  EXPECT_EQ(eaci::inflatedCosts(view, 0.05, sampleParameters()), std::vector<std::uint8_t>(6, 0));
}

TEST(Inflation, BadParametersAreNamed) {
  auto p = sampleParameters();
  EXPECT_EQ(eaci::inflationError(p), "");
  p.inflation_radius = -1;
  EXPECT_NE(eaci::inflationError(p).find("inflation_radius"), std::string::npos);
  p.inflation_radius = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(eaci::inflationError(p).find("inflation_radius"), std::string::npos);
  p = sampleParameters();
  p.inscribed_radius = 0.5;
  EXPECT_NE(eaci::inflationError(p).find("exceeds"), std::string::npos);
  p = sampleParameters();
  p.cost_scaling_factor = -2;
  EXPECT_NE(eaci::inflationError(p).find("cost_scaling_factor"), std::string::npos);
}

}  // namespace
