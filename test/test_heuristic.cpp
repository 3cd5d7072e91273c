// Eq. 9, 16, 17: heuristic values and the turning cost of every turn.
#include <gtest/gtest.h>

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

TEST(Heuristic, EtaValues) {
  EXPECT_DOUBLE_EQ(eaci::goalDistanceHeuristic(4.0), 0.25);              // Eq. 9
  EXPECT_DOUBLE_EQ(eaci::turningAwareHeuristic(4.0, 1.0), 0.2);          // Eq. 16
  EXPECT_DOUBLE_EQ(eaci::turningAwareHeuristic(2.0, 0.0), 0.5);
}
