// Route length and total corner angle.
#include <gtest/gtest.h>

#include <cmath>

#include "eaci/metrics/path_metrics.hpp"

using eaci::Cell;
using eaci::CellPath;

TEST(PathMetrics, LengthCountsStraightAsOneAndDiagonalAsRootTwo) {
  EXPECT_DOUBLE_EQ(eaci::pathLength({}), 0.0);
  EXPECT_DOUBLE_EQ(eaci::pathLength({Cell{3, 3}}), 0.0);
  EXPECT_NEAR(eaci::pathLength({{0, 0}, {0, 1}, {1, 2}, {2, 2}}), 2.0 + std::sqrt(2.0), 1e-12);
  // 30.97 = 14 + 12 sqrt2, the paper's 20x20 figure.
  CellPath p{{0, 0}};
  for (int k = 0; k < 12; ++k) p.push_back(Cell{p.back().row + 1, p.back().col + 1});
  for (int k = 0; k < 14; ++k) p.push_back(Cell{p.back().row, p.back().col + 1});
  EXPECT_NEAR(eaci::pathLength(p), 30.9706, 1e-4);
}

TEST(PathMetrics, TotalTurnAngleSumsTheTurnsInDegrees) {
  EXPECT_DOUBLE_EQ(eaci::totalTurnDegrees({{0, 0}, {0, 1}, {0, 2}}), 0.0);
  EXPECT_DOUBLE_EQ(eaci::totalTurnDegrees({{0, 0}, {0, 1}, {1, 2}, {2, 2}}), 90.0);   // 45 + 45
  EXPECT_DOUBLE_EQ(eaci::totalTurnDegrees({{0, 0}, {0, 1}, {1, 1}, {1, 0}}), 180.0);  // 90 + 90
  EXPECT_DOUBLE_EQ(eaci::totalTurnDegrees({{1, 0}, {1, 1}, {0, 0}}), 135.0);
}
