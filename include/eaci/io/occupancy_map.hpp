// An owned occupancy map as loaded from disk, with its place in the world.
#pragma once

#include <cstdint>
#include <vector>

#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/map_frame.hpp"

namespace eaci {

// Cell values, as in nav_msgs/OccupancyGrid (unknown -1 stored as the byte 255).
constexpr std::uint8_t kFreeValue = 0;
constexpr std::uint8_t kOccupiedValue = 100;
constexpr std::uint8_t kUnknownValue = 255;

// The map's size, resolution and origin (map_server's origin: the map-frame pose of the
// bottom-left corner of the bottom-left cell) with worldToCell / cellToWorld, and its cells.
struct OccupancyMap : MapFrame {
  std::vector<std::uint8_t> cells;  // row-major, row 0 = top; kFreeValue / kOccupiedValue / kUnknownValue

  GridView view(UnknownPolicy unknown = UnknownPolicy::kObstacle) const {
    CellInterpretation interpretation;
    interpretation.lethal_cost = kOccupiedValue;
    interpretation.unknown_value = kUnknownValue;
    interpretation.unknown = unknown;
    return GridView(cells.data(), width, height, RowOrder::kTopFirst, interpretation);
  }
};

}  // namespace eaci
