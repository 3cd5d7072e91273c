// The nearest free cell within a tolerance (include/eaci/grid/nearest_free.hpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <vector>

#include "eaci/grid/nearest_free.hpp"

namespace {

using eaci::Cell;

// 5 x 5, row 0 = top; 1 = obstacle.
const std::vector<std::uint8_t> kCells{
    0, 0, 0, 0, 0,
    0, 1, 1, 1, 0,
    0, 1, 1, 1, 0,
    0, 1, 1, 1, 0,
    0, 0, 0, 0, 0,
};

eaci::GridView sampleView() { return eaci::GridView(kCells.data(), 5, 5); }

TEST(NearestFree, FreeCellIsItself) { EXPECT_EQ(eaci::nearestFreeCell(sampleView(), Cell{0, 0}, 0.0), (Cell{0, 0})); }

TEST(NearestFree, NeighbourWithinTheRadius) {
  const auto view = sampleView();
  EXPECT_FALSE(eaci::nearestFreeCell(view, Cell{1, 1}, 0.5));  // every free cell is >= 1 away
  EXPECT_EQ(eaci::nearestFreeCell(view, Cell{1, 1}, 1.0), (Cell{0, 1}));  // (0,1) and (1,0) tie: row-major first
  EXPECT_EQ(eaci::nearestFreeCell(view, Cell{1, 2}, 1.0), (Cell{0, 2}));
}

TEST(NearestFree, CentreNeedsTwoCells) {
  const auto view = sampleView();
  EXPECT_FALSE(eaci::nearestFreeCell(view, Cell{2, 2}, 1.99));
  EXPECT_EQ(eaci::nearestFreeCell(view, Cell{2, 2}, 2.0), (Cell{0, 2}));
}

TEST(NearestFree, OffTheMapMovesOnto) {
  const auto view = sampleView();
  EXPECT_EQ(eaci::nearestFreeCell(view, Cell{-1, 3}, 1.0), (Cell{0, 3}));
  EXPECT_FALSE(eaci::nearestFreeCell(view, Cell{-3, 3}, 2.5));
  EXPECT_FALSE(eaci::nearestFreeCell(view, Cell{std::numeric_limits<int>::min(), 0}, 3.0));
}

TEST(NearestFree, BadRadiusFindsNothing) {
  const auto view = sampleView();
  EXPECT_FALSE(eaci::nearestFreeCell(view, Cell{1, 1}, -1.0));
  EXPECT_FALSE(eaci::nearestFreeCell(view, Cell{1, 1}, std::numeric_limits<double>::quiet_NaN()));
  EXPECT_EQ(eaci::nearestFreeCell(view, Cell{1, 1}, std::numeric_limits<double>::infinity()), (Cell{0, 1}));
}

}  // namespace
