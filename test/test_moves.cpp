// The move rule's helpers in grid/moves.hpp, by hand: the fewest 45-degree turns a route
// heading one way needs before it can reach a cell (the heading search's bound and the ants'
// look-ahead both use it).
#include <gtest/gtest.h>

#include "eaci/grid/moves.hpp"

TEST(TurnStepsAtLeast, TheAngleToTheGoalRoundedUpTo45Degrees) {
  // Heading east (direction 0: row 0, col +1); offsets as (rows, cols), rows down.
  EXPECT_EQ(eaci::turnStepsAtLeast(0, 0, 5), 0);    // straight on
  EXPECT_EQ(eaci::turnStepsAtLeast(0, 0, 0), 0);    // there already
  EXPECT_EQ(eaci::turnStepsAtLeast(0, -1, 5), 1);   // a little north of east
  EXPECT_EQ(eaci::turnStepsAtLeast(0, 5, 5), 1);    // exactly south-east: 45 degrees
  EXPECT_EQ(eaci::turnStepsAtLeast(0, -5, 1), 2);   // nearly north
  EXPECT_EQ(eaci::turnStepsAtLeast(0, 5, 0), 2);    // south: 90 degrees
  EXPECT_EQ(eaci::turnStepsAtLeast(0, -5, -1), 3);  // north, a little west
  EXPECT_EQ(eaci::turnStepsAtLeast(0, 4, -4), 3);   // exactly south-west: 135 degrees
  EXPECT_EQ(eaci::turnStepsAtLeast(0, 1, -5), 4);   // nearly behind
  EXPECT_EQ(eaci::turnStepsAtLeast(0, 0, -5), 4);   // behind
  // Heading north-east (direction 1: row -1, col +1).
  EXPECT_EQ(eaci::turnStepsAtLeast(1, -3, 3), 0);
  EXPECT_EQ(eaci::turnStepsAtLeast(1, 0, 3), 1);    // east
  EXPECT_EQ(eaci::turnStepsAtLeast(1, 1, 3), 2);    // a little south of east
  EXPECT_EQ(eaci::turnStepsAtLeast(1, 3, -3), 4);   // south-west: behind
}
