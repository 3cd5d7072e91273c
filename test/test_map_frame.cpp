// The world <-> cell transform (include/eaci/grid/map_frame.hpp) on a 4 x 3 grid of 0.5 m
// cells with its origin at (-1, 2): x runs from -1 to 1 m, y from 2 to 3.5 m.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "eaci/grid/map_frame.hpp"

using eaci::Cell;
using eaci::MapFrame;

namespace {

MapFrame sampleFrame() {
  MapFrame frame;
  frame.width = 4;
  frame.height = 3;
  frame.resolution = 0.5;
  frame.origin = {-1.0, 2.0};
  return frame;
}

}  // namespace

TEST(MapFrame, RowsCountFromTheTopAndYUpFromTheOrigin) {
  const MapFrame frame = sampleFrame();
  EXPECT_EQ(frame.worldToCell({-0.9, 2.1}), (Cell{2, 0}));  // just above the origin: the bottom row
  EXPECT_EQ(frame.worldToCell({-0.9, 3.4}), (Cell{0, 0}));  // the top row
  EXPECT_EQ(frame.worldToCell({0.9, 2.1}), (Cell{2, 3}));
  EXPECT_EQ(frame.worldToCell({-1.0, 2.0}), (Cell{2, 0}));  // a cell's left and bottom edges are its own
  EXPECT_EQ(frame.worldToCell({-0.5, 2.5}), (Cell{1, 1}));
  const Eigen::Vector2d top_left = frame.cellToWorld(Cell{0, 0});
  EXPECT_DOUBLE_EQ(top_left.x(), -0.75);
  EXPECT_DOUBLE_EQ(top_left.y(), 3.25);
  const Eigen::Vector2d bottom_right = frame.cellToWorld(Cell{2, 3});
  EXPECT_DOUBLE_EQ(bottom_right.x(), 0.75);
  EXPECT_DOUBLE_EQ(bottom_right.y(), 2.25);
}

TEST(MapFrame, EveryCellCentreMapsBackToItsCell) {
  const MapFrame frame = sampleFrame();
  for (int row = 0; row < frame.height; ++row)
    for (int col = 0; col < frame.width; ++col)
      EXPECT_EQ(frame.worldToCell(frame.cellToWorld(Cell{row, col})), (Cell{row, col}));
}

TEST(MapFrame, PointsOffTheGridHaveNoCell) {
  const MapFrame frame = sampleFrame();
  EXPECT_FALSE(frame.worldToCell({-1.01, 2.1}));  // left
  EXPECT_FALSE(frame.worldToCell({-0.9, 1.99}));  // below
  EXPECT_FALSE(frame.worldToCell({1.0, 2.1}));    // x = origin + width: the right edge is off the grid
  EXPECT_FALSE(frame.worldToCell({-0.9, 3.5}));   // y = origin + height: the top edge too
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(frame.worldToCell({std::nan(""), 2.1}));
  EXPECT_FALSE(frame.worldToCell({-0.9, inf}));
  EXPECT_FALSE(frame.worldToCell({-inf, 2.1}));
}

TEST(MapFrame, ANonPositiveOrNanResolutionPlacesNothing) {
  MapFrame frame = sampleFrame();
  for (double resolution : {0.0, -0.5, std::nan("")}) {
    frame.resolution = resolution;
    EXPECT_FALSE(frame.worldToCell({-0.9, 2.1})) << "resolution " << resolution;
  }
}

TEST(MapFrame, TheOriginYawIsIgnoredLikeCostmap2dDoes) {
  MapFrame turned = sampleFrame();
  turned.origin_yaw = 0.3;
  EXPECT_EQ(turned.worldToCell({0.9, 2.1}), (Cell{2, 3}));
  EXPECT_EQ(turned.cellToWorld(Cell{2, 3}), sampleFrame().cellToWorld(Cell{2, 3}));
}
