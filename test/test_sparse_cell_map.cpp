// SparseCellMap: a value per cell of a window, held in 16 x 16 blocks made on first write.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <random>
#include <utility>

#include "eaci/grid/sparse_cell_map.hpp"

using eaci::Cell;
using eaci::CellWindow;
using eaci::SparseCellMap;

TEST(SparseCellMap, ReadsWhatWasWrittenAndNoneElsewhere) {
  SparseCellMap map;
  map.reset(CellWindow{5, 7, 40, 33});  // rows 5..44, columns 7..39: blocks not aligned to 16
  EXPECT_EQ(map.get(Cell{5, 7}), SparseCellMap::kNone);
  map.at(Cell{5, 7}) = 1;
  map.at(Cell{20, 22}) = 2;   // the first block's last cell (row 15, column 15 of the window)
  map.at(Cell{21, 23}) = 3;   // the next block down and right
  map.at(Cell{44, 39}) = 4;   // the window's last cell
  EXPECT_EQ(map.get(Cell{5, 7}), 1u);
  EXPECT_EQ(map.get(Cell{20, 22}), 2u);
  EXPECT_EQ(map.get(Cell{21, 23}), 3u);
  EXPECT_EQ(map.get(Cell{44, 39}), 4u);
  EXPECT_EQ(map.get(Cell{20, 23}), SparseCellMap::kNone);
  EXPECT_EQ(map.get(Cell{4, 7}), SparseCellMap::kNone);    // above the window
  EXPECT_EQ(map.get(Cell{45, 39}), SparseCellMap::kNone);  // below it
  EXPECT_EQ(map.get(Cell{5, 40}), SparseCellMap::kNone);   // right of it
  // (5,7) and (20,22) share the first block; (21,23) and (44,39) have one each.
  EXPECT_EQ(map.valuesHeld(), 3 * SparseCellMap::kBlockCells);
}

TEST(SparseCellMap, HoldsBlocksOnlyWhereWrittenAndForgetsOnReset) {
  SparseCellMap map;
  map.reset(CellWindow{0, 0, 4000, 4000});  // 16 M cells
  for (int k = 0; k < 4000; ++k) map.at(Cell{k, k}) = static_cast<std::uint32_t>(k);  // the diagonal
  EXPECT_EQ(map.valuesHeld(), 250 * SparseCellMap::kBlockCells);  // 4000 / 16 blocks on the diagonal
  EXPECT_EQ(map.get(Cell{1234, 1234}), 1234u);
  EXPECT_EQ(map.get(Cell{1234, 1235}), SparseCellMap::kNone);
  map.reset(CellWindow{0, 0, 4000, 4000});
  EXPECT_EQ(map.get(Cell{1234, 1234}), SparseCellMap::kNone);
  EXPECT_EQ(map.valuesHeld(), 0u);
}

TEST(SparseCellMap, AgreesWithAnOrderedMapOnRandomWrites) {
  std::mt19937 rng(3);
  SparseCellMap map;
  for (int round = 0; round < 5; ++round) {
    const CellWindow window{static_cast<int>(rng() % 50), static_cast<int>(rng() % 50), 1 + static_cast<int>(rng() % 90),
                            1 + static_cast<int>(rng() % 90)};
    map.reset(window);
    std::map<std::pair<int, int>, std::uint32_t> expected;
    for (int k = 0; k < 500; ++k) {
      const Cell c{window.row0 + static_cast<int>(rng() % static_cast<unsigned>(window.rows)),
                   window.col0 + static_cast<int>(rng() % static_cast<unsigned>(window.cols))};
      const auto value = static_cast<std::uint32_t>(rng() % 1000);
      map.at(c) = value;
      expected[{c.row, c.col}] = value;
    }
    for (int r = window.row0 - 1; r <= window.row0 + window.rows; ++r)
      for (int c = window.col0 - 1; c <= window.col0 + window.cols; ++c) {
        const auto it = expected.find({r, c});
        EXPECT_EQ(map.get(Cell{r, c}), it == expected.end() ? SparseCellMap::kNone : it->second) << r << "," << c;
      }
  }
}
