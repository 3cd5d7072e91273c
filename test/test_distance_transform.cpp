// The exact Euclidean distance transform (include/eaci/grid/distance_transform.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "eaci/grid/distance_transform.hpp"
#include "eaci/grid/grid_view.hpp"

namespace {

double at(const std::vector<double>& d, int width, int row, int col) { return d[static_cast<std::size_t>(row * width + col)]; }

TEST(DistanceTransform, OneObstacleGivesEuclideanDistances) {
  std::vector<std::uint8_t> cells(25, 0);
  cells[2 * 5 + 2] = 1;  // (2,2) on a 5 x 5 map
  const eaci::GridView view(cells.data(), 5, 5);
  const std::vector<double> d = eaci::obstacleDistances(view);
  ASSERT_EQ(d.size(), 25u);
  EXPECT_EQ(at(d, 5, 2, 2), 0.0);
  EXPECT_EQ(at(d, 5, 2, 3), 1.0);
  EXPECT_EQ(at(d, 5, 1, 1), std::sqrt(2.0));
  EXPECT_EQ(at(d, 5, 0, 2), 2.0);
  EXPECT_EQ(at(d, 5, 0, 1), std::sqrt(5.0));
  EXPECT_EQ(at(d, 5, 0, 0), std::sqrt(8.0));
  EXPECT_EQ(at(d, 5, 4, 4), std::sqrt(8.0));
}

TEST(DistanceTransform, NearestOfSeveralObstacles) {
  const std::vector<std::uint8_t> sources{1, 0, 0, 0, 0, 1};  // one row of 6
  const std::vector<double> d2 = eaci::squaredDistancesToSources(6, 1, sources);
  EXPECT_EQ(d2, (std::vector<double>{0, 1, 4, 4, 1, 0}));
  const std::vector<double> column = eaci::squaredDistancesToSources(1, 6, sources);  // one column of 6
  EXPECT_EQ(column, d2);
}

TEST(DistanceTransform, NoObstacleIsInfinitelyFar) {
  const std::vector<double> d2 = eaci::squaredDistancesToSources(3, 2, std::vector<std::uint8_t>(6, 0));
  ASSERT_EQ(d2.size(), 6u);
  for (double x : d2) EXPECT_EQ(x, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(eaci::squaredDistancesToSources(0, 4, {}).empty());
}

TEST(DistanceTransform, UnknownCellsAreNotObstaclesToMeasureFrom) {
  const std::vector<std::uint8_t> cells{255, 0, 0, 100};  // unknown, free, free, occupied
  eaci::CellInterpretation map_file;
  map_file.lethal_cost = 100;
  const eaci::GridView view(cells.data(), 4, 1, eaci::RowOrder::kTopFirst, map_file);
  EXPECT_EQ(eaci::obstacleDistances(view), (std::vector<double>{3, 2, 1, 0}));
}

// Exact: equal to the brute-force minimum over all obstacles on a random map.
TEST(DistanceTransform, EqualsBruteForceOnARandomMap) {
  const int w = 17, h = 13;
  std::mt19937 rng(7);
  std::vector<std::uint8_t> sources(static_cast<std::size_t>(w * h));
  for (auto& s : sources) s = rng() % 9 == 0 ? 1 : 0;
  const std::vector<double> d2 = eaci::squaredDistancesToSources(w, h, sources);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      double best = std::numeric_limits<double>::infinity();
      for (int sr = 0; sr < h; ++sr)
        for (int sc = 0; sc < w; ++sc)
          if (sources[static_cast<std::size_t>(sr * w + sc)]) best = std::min(best, double((r - sr) * (r - sr) + (c - sc) * (c - sc)));
      EXPECT_EQ(at(d2, w, r, c), best) << r << "," << c;
    }
  }
}

}  // namespace
