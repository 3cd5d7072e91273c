// The nearest free cell within a tolerance (include/eaci/grid/nearest_free.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
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

// The reference: every cell of the square of side 2 r + 1 around `cell`, in row-major order,
// the nearest free one within the radius (the first of equally near ones).
std::optional<Cell> bruteForceNearest(const eaci::GridView& view, Cell cell, double radius) {
  if (view.isFree(cell)) return cell;
  if (!(radius >= 0)) return std::nullopt;
  std::optional<Cell> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int r = 0; r < view.height(); ++r)
    for (int c = 0; c < view.width(); ++c) {
      const double d = std::hypot(double(r) - cell.row, double(c) - cell.col);
      if (d > radius || d >= best_distance || !view.isFree(Cell{r, c})) continue;
      best = Cell{r, c};
      best_distance = d;
    }
  return best;
}

TEST(NearestFree, AgreesWithABruteForceScanOnRandomMaps) {
  std::mt19937 random(21);
  for (int trial = 0; trial < 400; ++trial) {
    const int width = 1 + static_cast<int>(random() % 30), height = 1 + static_cast<int>(random() % 30);
    const double free_share = (random() % 100) / 400.0;  // 0 .. 25 % free: the answer is often far
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(width) * height);
    for (auto& v : cells) v = std::uniform_real_distribution<double>(0, 1)(random) < free_share ? 0 : 1;
    const eaci::GridView view(cells.data(), width, height);
    const Cell cell{static_cast<int>(random() % (height + 20)) - 10, static_cast<int>(random() % (width + 20)) - 10};
    const double radii[] = {0.0, 1.0, 1.5, 2.0, 3.7, 10.0, 1e9, std::numeric_limits<double>::infinity()};
    for (double radius : radii)
      EXPECT_EQ(eaci::nearestFreeCell(view, cell, radius), bruteForceNearest(view, cell, radius))
          << "trial " << trial << " (" << width << " x " << height << ") cell " << cell.row << "," << cell.col
          << " radius " << radius;
  }
}

TEST(NearestFree, HugeRadiusOnABigMapVisitsOnlyTheCellsNearTheAnswer) {
  // 3000 x 3000 cells of obstacle with free cells 30 and 100 cells from the query, radius 1e9:
  // a scan of the square would visit 36 million cells (a stop check called ~8800 times); the
  // rings up to 30 hold 61 x 61 = 3721 cells, under one check's 4096, and those up to 100
  // 201 x 201 = 40401 cells, 9 checks.
  const int side = 3000;
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(side) * side, 1);
  const auto set_free = [&](int r, int c) { cells[static_cast<std::size_t>(r) * side + c] = 0; };
  set_free(2999, 2999);  // far away
  set_free(1500 + 100, 1500);  // 100 below the query
  const eaci::GridView view(cells.data(), side, side);
  int calls = 0;
  const std::function<bool()> counting = [&] {
    ++calls;
    return false;
  };
  EXPECT_EQ(eaci::nearestFreeCell(view, Cell{1500, 1500}, 1e9, counting), (Cell{1600, 1500}));
  EXPECT_LE(calls, 10);
  set_free(1500 - 18, 1500 + 24);  // 30 away (18^2 + 24^2 = 30^2)
  calls = 0;
  EXPECT_EQ(eaci::nearestFreeCell(view, Cell{1500, 1500}, 1e9, counting), (Cell{1482, 1524}));
  EXPECT_EQ(calls, 0);
  // A check that says stop ends the search with none.
  const eaci::StopCheck stop = [](int) { return true; };
  EXPECT_FALSE(eaci::nearestFreeCell(view, Cell{0, 0}, 1e9, stop));
  // From a corner the only free cells are far: the answer is still the brute-force one.
  EXPECT_EQ(eaci::nearestFreeCell(view, Cell{0, 0}, 1e9), (Cell{1482, 1524}));
}

}  // namespace
