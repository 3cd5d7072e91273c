// eaci_plan's picture: the map, the pheromone, the auxiliary-map obstacles, the islands,
// the path, start and goal, drawn by a small rasteriser and written as PNG with stb.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
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

struct PlanDrawing {
  const OccupancyMap* map = nullptr;                 // required
  UnknownPolicy unknown = UnknownPolicy::kObstacle;  // how unknown cells were planned
  const PlanResult* result = nullptr;                // path, islands, pheromone; may be null
  std::optional<Cell> start;                          // drawn when on the map
  std::optional<Cell> goal;
  // Per cell (row-major): 1 where EACI's auxiliary map (Eq. 12) turned a free cell into an
  // obstacle. Empty: none drawn.
  std::vector<std::uint8_t> auxiliary_blocked;
  std::string caption;                               // one line under the map (ASCII)
};

// Pixels per cell edge: clamp(1000 / max(W, H), 1, 24).
int cellPixels(int width, int height);

// Draws the plan. Throws std::invalid_argument when `map` is null or empty.
RgbImage renderPlan(const PlanDrawing& drawing);

// Writes an RGB image as PNG. Throws std::runtime_error with a one-line reason.
void writePng(const std::string& file, const RgbImage& image);

}  // namespace eaci::tools
