// An owned occupancy map as loaded from disk, with its place in the world.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_numbering.hpp"
#include "eaci/grid/grid_view.hpp"

namespace eaci {

// Cell values, as in nav_msgs/OccupancyGrid (unknown -1 stored as the byte 255).
constexpr std::uint8_t kFreeValue = 0;
constexpr std::uint8_t kOccupiedValue = 100;
constexpr std::uint8_t kUnknownValue = 255;

struct OccupancyMap {
  int width = 0;
  int height = 0;
  double resolution = 1.0;  // metres per cell
  // Map-frame pose of the bottom-left corner of the bottom-left cell (map_server's origin).
  double origin_x = 0.0;
  double origin_y = 0.0;
  double origin_yaw = 0.0;  // kept for reference; like costmap_2d, positions ignore it
  std::vector<std::uint8_t> cells;  // row-major, row 0 = top; kFreeValue / kOccupiedValue / kUnknownValue

  GridView view(UnknownPolicy unknown = UnknownPolicy::kObstacle) const {
    CellInterpretation interpretation;
    interpretation.obstacle_threshold = kOccupiedValue;
    interpretation.unknown_value = kUnknownValue;
    interpretation.unknown = unknown;
    return GridView(cells.data(), width, height, RowOrder::kTopFirst, interpretation);
  }

  // Cell containing the map-frame point (x, y), or nothing when it lies off the map.
  std::optional<Cell> cellAtWorld(double x, double y) const {
    if (!std::isfinite(x) || !std::isfinite(y) || resolution <= 0) return std::nullopt;
    const double col = std::floor((x - origin_x) / resolution);
    const double row_from_bottom = std::floor((y - origin_y) / resolution);
    if (col < 0 || row_from_bottom < 0 || col >= width || row_from_bottom >= height) return std::nullopt;
    return Cell{height - 1 - static_cast<int>(row_from_bottom), static_cast<int>(col)};
  }

  // Map-frame centre of a cell.
  Eigen::Vector2d worldAtCell(Cell c) const {
    return Eigen::Vector2d(origin_x, origin_y) + cellCentre(c, height, resolution);
  }
};

}  // namespace eaci
