// Eq. 1-4: serial numbers and cell centres, against the paper's 10 x 10 example.
#include <gtest/gtest.h>

#include "eaci/grid/cell_numbering.hpp"

using eaci::Cell;

TEST(CellNumbering, SerialNumbersRunLeftToRightTopToBottom) {
  EXPECT_EQ(eaci::cellFromSerial(1, 10), (Cell{0, 0}));
  EXPECT_EQ(eaci::cellFromSerial(3, 10), (Cell{0, 2}));    // the paper's start in Figure 6
  EXPECT_EQ(eaci::cellFromSerial(25, 10), (Cell{2, 4}));
  EXPECT_EQ(eaci::cellFromSerial(100, 10), (Cell{9, 9}));
  EXPECT_EQ(eaci::cellFromSerial(2450, 50), (Cell{48, 49}));
}

TEST(CellNumbering, SerialToCell) {
  EXPECT_EQ(eaci::cellFromSerial(1, 20), (Cell{0, 0}));
  EXPECT_EQ(eaci::cellFromSerial(400, 20), (Cell{19, 19}));
  EXPECT_EQ(eaci::cellFromSerial(871, 30), (Cell{29, 0}));  // 30x30 start
  EXPECT_EQ(eaci::cellFromSerial(30, 30), (Cell{0, 29}));   // 30x30 goal
  EXPECT_EQ(eaci::cellFromSerial(2451, 50), (Cell{49, 0}));
  EXPECT_EQ(eaci::cellFromSerial(50, 50), (Cell{0, 49}));
  // Counting the cells of a 3 x 4 map left to right, top to bottom gives their serial numbers.
  int g = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(eaci::cellFromSerial(++g, 4), (Cell{r, c})) << g;
}

TEST(CellNumbering, CentreCoordinatesHaveTheOriginBottomLeft) {
  // Eq. 3-4 with 1-based r, c: x = (c - 0.5) a, y = (H - r + 0.5) a.
  const auto top_left = eaci::cellCentre(Cell{0, 0}, 10, 1.0);
  EXPECT_DOUBLE_EQ(top_left.x(), 0.5);
  EXPECT_DOUBLE_EQ(top_left.y(), 9.5);
  const auto g25 = eaci::cellCentre(Cell{2, 4}, 10, 0.2);  // r = 3, c = 5
  EXPECT_DOUBLE_EQ(g25.x(), 4.5 * 0.2);
  EXPECT_DOUBLE_EQ(g25.y(), 7.5 * 0.2);
  const auto bottom_right = eaci::cellCentre(Cell{9, 9}, 10, 1.0);
  EXPECT_DOUBLE_EQ(bottom_right.x(), 9.5);
  EXPECT_DOUBLE_EQ(bottom_right.y(), 0.5);
}
