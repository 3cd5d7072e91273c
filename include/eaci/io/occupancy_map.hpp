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

// costmap_2d's INSCRIBED_INFLATED_OBSTACLE: in a map of costs, cells of this cost and above
// are obstacles unless the planner is told another lethal cost (Parameters::lethal_cost).
constexpr std::uint8_t kDefaultLethalCost = 253;

// What a map's cell bytes mean.
//   kOccupancy:    kFreeValue / kOccupiedValue / kUnknownValue (map_server's trinary mode, 0/1 text)
//   kCostmapCosts: costmap_2d costs: 0 free, 1..252 a cost, 253 / 254 obstacles, 255 unknown
//                  (map_server's raw mode: each pixel as it is)
enum class CellValues { kOccupancy, kCostmapCosts };

// The map's size, resolution and origin (map_server's origin: the map-frame pose of the
// bottom-left corner of the bottom-left cell) with worldToCell / cellToWorld, and its cells.
struct OccupancyMap : MapFrame {
  std::vector<std::uint8_t> cells;  // row-major, row 0 = top; see `values`
  CellValues values = CellValues::kOccupancy;

  // The cells as the planners read them. `lethal_cost` applies to maps of costs only: cells of
  // that cost and above are obstacles there (occupancy maps: kOccupiedValue). Unknown cells
  // (255 in both kinds) follow `unknown`.
  GridView view(UnknownPolicy unknown = UnknownPolicy::kObstacle,
                std::uint8_t lethal_cost = kDefaultLethalCost) const {
    CellInterpretation interpretation;
    if (values == CellValues::kCostmapCosts) {
      interpretation = CellInterpretation::costmap(lethal_cost, unknown == UnknownPolicy::kExpensive);
    } else {
      interpretation.lethal_cost = kOccupiedValue;
      interpretation.unknown = unknown;
    }
    interpretation.unknown_value = kUnknownValue;
    return GridView(cells.data(), width, height, RowOrder::kTopFirst, interpretation);
  }
};

}  // namespace eaci
