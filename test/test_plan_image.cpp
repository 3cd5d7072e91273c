// The CLI's picture (src/tools/plan_image): the cost ramp, the thinning of island markers, the
// routes' caption lines, and the smoothed route drawn over the grid route.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "../src/tools/plan_image.hpp"

namespace {

using eaci::Cell;
using eaci::CellPath;
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

// A free 30 x 20 map; the grid route runs right along row 16 from column 3 to 14, then
// diagonally up to (4, 26); the smoothed route keeps row 16 to column 10, then goes straight to
// (4, 26): 12 rows up and 16 columns right, a 3-4-5 triangle of 20 cells.
struct TwoRoutes {
  eaci::OccupancyMap map;
  eaci::PlanResult result;

  TwoRoutes() {
    map.width = 30;
    map.height = 20;
    map.resolution = 0.05;
    map.cells.assign(30 * 20, eaci::kFreeValue);
    result.status = eaci::PlanStatus::kSuccess;
    for (int c = 3; c <= 14; ++c) result.path.push_back({16, c});
    for (int s = 1; s <= 12; ++s) result.path.push_back({16 - s, 14 + s});
    result.length = 11 + 12 * std::sqrt(2.0);
    result.total_turn_deg = 45 + 45;  // onto the diagonal, and none at the goal
    result.smoothed_path = {{16, 3}, {16, 10}, {4, 26}};
    result.smoothed_length = 7 + 20;
    result.islands = {{16, 3}, {4, 26}};
  }
};

std::array<std::uint8_t, 3> pixelAt(const eaci::tools::RgbImage& image, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 3;
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

std::size_t countColour(const eaci::tools::RgbImage& image, std::array<std::uint8_t, 3> colour, int y0, int y1) {
  std::size_t n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < image.width; ++x) n += pixelAt(image, x, y) == colour ? 1 : 0;
  return n;
}

TEST(PlanImage, CaptionGivesBothRoutesLengthsAndTurns) {
  TwoRoutes two;
  // 11 + 12 sqrt 2 = 27.97 cells = 1.40 m at 0.05 m/cell; the smoothed route turns once, by
  // the angle between (1, 0) and (16, -12) / 20: acos(0.8) = 36.87 degrees.
  EXPECT_EQ(eaci::tools::routeCaptionLines(two.result, 0.05, true),
            (std::vector<std::string>{"grid route (8-connected): 27.97 cells = 1.4 m, total turn 90 deg",
                                      "smoothed route (driven): 27 cells = 1.35 m, total turn 37 deg"}));
  EXPECT_EQ(eaci::tools::routeCaptionLines(two.result, 1.0, false),
            (std::vector<std::string>{"route: 27.97 cells, total turn 90 deg"}));
}

TEST(PlanImage, SmoothedRouteIsDrawnOverTheGridRoute) {
  TwoRoutes two;
  eaci::tools::PlanDrawing drawing;
  drawing.map = &two.map;
  drawing.result = &two.result;
  drawing.start = Cell{16, 3};
  drawing.goal = Cell{4, 26};
  drawing.smoothed = true;
  const eaci::tools::PlanImage picture = eaci::tools::renderPlan(drawing);
  const eaci::tools::RgbImage& image = picture.image;
  const int k = picture.cell_pixels;
  ASSERT_EQ(k, 24);  // 1000 / 30 cells, at most 24
  // The pixel under a point given in cells (column, row from the top), cell centres at + 0.5.
  auto at = [&](double col, double row) {
    return pixelAt(image, picture.map_left + static_cast<int>(std::floor((col + 0.5) * k)),
                   picture.map_top + static_cast<int>(std::floor((row + 0.5) * k)));
  };
  const auto smoothed = eaci::tools::kSmoothedRouteColour;
  const auto grid = eaci::tools::kGridRouteColour;
  ASSERT_NE(smoothed, grid);

  // Along the smoothed route's diagonal leg, away from the markers and from the grid route.
  for (double t = 0.25; t <= 0.75; t += 0.05) EXPECT_EQ(at(10 + 16 * t, 16 - 12 * t), smoothed) << "t " << t;
  // Where both run along row 16 the smoothed route is on top, the grid route's wider line shows
  // beside it (a quarter cell above and below the centre line).
  for (int col = 6; col <= 8; ++col) {
    EXPECT_EQ(at(col, 16), smoothed) << "col " << col;
    EXPECT_EQ(at(col, 16 - 0.25), grid) << "col " << col;
    EXPECT_EQ(at(col, 16 + 0.25), grid) << "col " << col;
  }
  // Where the smoothed route has cut the corner, the grid route's cells (2 to 3 rows off it).
  for (const Cell c : CellPath{{16, 12}, {16, 13}, {15, 15}, {14, 16}}) EXPECT_EQ(at(c.col, c.row), grid) << c.col;
  // Nothing off the routes is in their colours.
  EXPECT_NE(at(20, 16), smoothed);
  EXPECT_NE(at(20, 16), grid);

  // The legend, below the map, has a swatch of each.
  const int below_map = picture.map_top + two.map.height * k;
  EXPECT_GE(countColour(image, smoothed, below_map, image.height), 20u);
  EXPECT_GE(countColour(image, grid, below_map, image.height), 20u);

  // Without smoothing, one route, and nothing in the smoothed route's colour.
  drawing.smoothed = false;
  const eaci::tools::PlanImage plain = eaci::tools::renderPlan(drawing);
  EXPECT_EQ(countColour(plain.image, smoothed, 0, plain.image.height), 0u);
  EXPECT_EQ(pixelAt(plain.image, plain.map_left + 7 * k + k / 2, plain.map_top + 16 * k + k / 2), grid);
}

}  // namespace
