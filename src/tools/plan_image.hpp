// eaci_plan's picture: the map, the pheromone, the auxiliary-map obstacles, the islands,
// the grid route and the smoothed route, start and goal, drawn by a small rasteriser and
// written as PNG with stb.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/io/occupancy_map.hpp"
#include "eaci/planner.hpp"

namespace eaci::tools {

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // row-major, 3 bytes per pixel, row 0 = top
};

// A drawn plan and where its map sits in it: cell (row, col) covers the pixels
// [map_left + col x cell_pixels, + cell_pixels) x [map_top + row x cell_pixels, + cell_pixels).
struct PlanImage {
  RgbImage image;
  int map_left = 0;
  int map_top = 0;
  int cell_pixels = 1;
};

// The routes' colours: the 8-connected grid route the ants found (blue) and the smoothed route
// a robot drives (magenta, wider, drawn over it).
constexpr std::array<std::uint8_t, 3> kGridRouteColour{20, 80, 235};
constexpr std::array<std::uint8_t, 3> kSmoothedRouteColour{215, 0, 150};

struct PlanDrawing {
  const OccupancyMap* map = nullptr;                 // required
  UnknownPolicy unknown = UnknownPolicy::kObstacle;  // how unknown cells were planned
  std::uint8_t lethal_cost = kDefaultLethalCost;     // maps of costs (mode: raw): obstacles from this cost up
  const PlanResult* result = nullptr;                // path, islands, pheromone; may be null
  std::optional<Cell> start;                          // drawn when on the map
  std::optional<Cell> goal;
  // Per cell (row-major): 1 where EACI's auxiliary map (Eq. 12) turned a free cell into an
  // obstacle. Empty: none drawn.
  std::vector<std::uint8_t> auxiliary_blocked;
  std::string caption;                               // lines under the map (ASCII, '\n' between)
  // The cells the planners read when they are not the map's own (--inflate: the map's costmap_2d
  // costs): their costs are drawn, and cells that are obstacles there but free on the map
  // (the inscribed band) in the darkest cost grey. Empty: the map.
  std::optional<GridView> planned_on;
  // The route was smoothed (smooth_path): result->smoothed_path, the route a robot drives, is
  // drawn over the grid route (result->path) and the legend names both; else one route.
  bool smoothed = false;
};

// Pixels per cell edge: clamp(1000 / max(W, H), 1, 24).
int cellPixels(int width, int height);

// The grey of a free cell of cost 0..254 (CostGrid::cost): cost 0 white (255), cost 254 a
// dark grey (80), linear between, so obstacles (black) stay apart from the darkest cost.
constexpr std::uint8_t costGrey(std::uint8_t cost) {
  return static_cast<std::uint8_t>(255 - (static_cast<int>(cost) * (255 - 80) + 127) / 254);
}

// Islands to draw on a route: with markers of `spacing` pixels or more apart (at their
// centres, given in pixels in route order), a marker closer than that to the last one drawn
// is left out, so on a large map the markers do not cover the route. Returns the indices kept.
inline std::vector<std::size_t> thinMarkers(const std::vector<std::pair<double, double>>& centres, double spacing) {
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (!kept.empty()) {
      const auto& last = centres[kept.back()];
      const double dx = centres[i].first - last.first, dy = centres[i].second - last.second;
      if (dx * dx + dy * dy < spacing * spacing) continue;
    }
    kept.push_back(i);
  }
  return kept;
}

// The caption's lines on a successful plan's routes, lengths in cells with two decimals (and in
// metres when `resolution` is not 1), total turns in whole degrees:
//   smoothed: "grid route (8-connected): 112.87 cells = 5.64 m, total turn 900 deg"
//             "smoothed route (driven): 111.54 cells = 5.58 m, total turn 324 deg"
//   else one line "route: ..." with the grid route's figures.
// The smoothed route's turn is totalTurnDegrees(smoothed_path) (its corners).
std::vector<std::string> routeCaptionLines(const PlanResult& result, double resolution, bool smoothed);

// Draws the plan. Throws std::invalid_argument when `map` is null or empty.
PlanImage renderPlan(const PlanDrawing& drawing);

// Writes an RGB image as PNG. Throws std::runtime_error with a one-line reason.
void writePng(const std::string& file, const RgbImage& image);

}  // namespace eaci::tools
