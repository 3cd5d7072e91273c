// The picture's cost ramp and the thinning of island markers (header-only parts of the CLI's
// plan_image).
#include <gtest/gtest.h>

#include <cstddef>
#include <utility>
#include <vector>

#include "../src/tools/plan_image.hpp"

using eaci::tools::costGrey;
using eaci::tools::thinMarkers;

TEST(PlanImage, CostGreyRunsFromWhiteToDarkGrey) {
  EXPECT_EQ(costGrey(0), 255);   // free, cost 0: white
  EXPECT_EQ(costGrey(254), 80);  // the highest cost: dark grey, lighter than an obstacle's black
  EXPECT_EQ(costGrey(127), 167);  // half way: 255 - round(127 x 175 / 254) = 255 - 88
  for (int c = 1; c <= 254; ++c) EXPECT_LE(costGrey(static_cast<std::uint8_t>(c)), costGrey(static_cast<std::uint8_t>(c - 1)));
}

TEST(PlanImage, ThinMarkersKeepsMarkersSpacedApart) {
  const std::vector<std::pair<double, double>> centres = {{0, 0}, {3, 4}, {6, 8}, {20, 8}, {21, 8}, {30, 8}};
  EXPECT_EQ(thinMarkers(centres, 0.0), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(thinMarkers(centres, 5.0), (std::vector<std::size_t>{0, 1, 2, 3, 5}));  // (21, 8) is 1 from (20, 8)
  EXPECT_EQ(thinMarkers(centres, 10.0), (std::vector<std::size_t>{0, 2, 3, 5}));   // (6, 8) is exactly 10 from (0, 0)
  EXPECT_TRUE(thinMarkers({}, 10.0).empty());
}
