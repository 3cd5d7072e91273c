// Non-owning view of an occupancy grid stored as a row-major byte buffer.
//
// The view can sit on a costmap_2d char map, on the int8 data of a
// nav_msgs/OccupancyGrid or on a map loaded by eaci::io without copying.
// How a byte value maps to obstacle / cost is the CellInterpretation's job.
#pragma once

#include <cstddef>
#include <cstdint>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/costmap_costs.hpp"

namespace eaci {

// costmap_2d's dearest passable cost, kCostmapDearestPassable (INSCRIBED_INFLATED_OBSTACLE - 1):
// an unknown cell that may be crossed costs this on maps whose values are not costs (map
// files, OccupancyGrid, 0/1 maps), so that the CostRule prices it as on a costmap.

// What an unknown cell is: an obstacle, or passable at the dearest cost a passable cell can
// have (allow_unknown), as navfn (COST_OBS - 1) and global_planner (lethal_cost - 1) price it:
// a route crosses unknown space only where every way round through known space costs more.
enum class UnknownPolicy { kObstacle, kExpensive };

// Byte value -> obstacle or cost: the one interpreter of map bytes, whatever their source.
// A value equal to `unknown_value` is unknown: an obstacle, or (kExpensive, unknown cells
// allowed) a passable cell of unknownCost(); any other value at or above `lethal_cost` is an
// obstacle; every other cell is free, with its value as its cost when the values are graded
// (costmap_2d: 0 free .. 252 inscribed, the inflation gradient), else with cost 0.
//   plain 0/1 maps:         lethal 1,   unknown never occurs,      not graded
//   map files, OccupancyGrid: lethal 100 / 65, unknown 255 (= int8 -1), not graded
//   costmap_2d:             lethal 253, unknown 255 (NO_INFORMATION), graded
struct CellInterpretation {
  std::uint8_t lethal_cost = 1;
  std::uint8_t unknown_value = 255;
  UnknownPolicy unknown = UnknownPolicy::kObstacle;
  bool graded = false;

  // costmap_2d's char map with its own lethal cost (253 = inscribed inflated obstacle).
  static CellInterpretation costmap(std::uint8_t lethal_cost, bool allow_unknown) {
    return {lethal_cost, 255, allow_unknown ? UnknownPolicy::kExpensive : UnknownPolicy::kObstacle, true};
  }

  bool isObstacle(std::uint8_t value) const {
    if (value == unknown_value) return unknown == UnknownPolicy::kObstacle;
    return value >= lethal_cost;
  }
  // The cost of a passable unknown cell: the dearest a passable cell can cost, lethal_cost - 1
  // on graded maps (costmap_2d: 252), kCostmapDearestPassable on the others.
  std::uint8_t unknownCost() const {
    if (!graded) return kCostmapDearestPassable;
    return lethal_cost > 0 ? static_cast<std::uint8_t>(lethal_cost - 1) : 0;
  }
  // The cost 0..254 of a cell that is not an obstacle.
  std::uint8_t cost(std::uint8_t value) const {
    if (value == unknown_value) return unknownCost();
    return graded ? value : 0;
  }
};

// Which buffer row holds the top row of the map. Images and the paper's
// matrices store the top row first; nav_msgs/OccupancyGrid and costmap_2d
// store the bottom row (the one at the map origin) first.
enum class RowOrder { kTopFirst, kBottomFirst };

class GridView {
 public:
  GridView() = default;
  GridView(const std::uint8_t* data, int width, int height, RowOrder order = RowOrder::kTopFirst,
           CellInterpretation interpretation = {})
      : data_(data), width_(width), height_(height), order_(order), interpretation_(interpretation) {}

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t cellCount() const {
    return static_cast<std::size_t>(width_ > 0 ? width_ : 0) * static_cast<std::size_t>(height_ > 0 ? height_ : 0);
  }
  bool empty() const { return data_ == nullptr || cellCount() == 0; }
  const CellInterpretation& interpretation() const { return interpretation_; }

  bool contains(Cell c) const { return c.row >= 0 && c.col >= 0 && c.row < height_ && c.col < width_; }

  // Raw byte of cell c (row 0 = top of the map, whatever the buffer order).
  std::uint8_t value(Cell c) const {
    const int buffer_row = order_ == RowOrder::kTopFirst ? c.row : height_ - 1 - c.row;
    return data_[static_cast<std::size_t>(buffer_row) * static_cast<std::size_t>(width_) +
                 static_cast<std::size_t>(c.col)];
  }

  // The bytes of map row `row` (0 = top), width() of them, whatever the buffer order.
  const std::uint8_t* rowBytes(int row) const {
    const int buffer_row = order_ == RowOrder::kTopFirst ? row : height_ - 1 - row;
    return data_ + static_cast<std::size_t>(buffer_row) * static_cast<std::size_t>(width_);
  }

  bool isObstacle(Cell c) const { return interpretation_.isObstacle(value(c)); }
  // The cost 0..254 of a free cell (see CellInterpretation).
  std::uint8_t cost(Cell c) const { return interpretation_.cost(value(c)); }
  bool isFree(Cell c) const { return contains(c) && !isObstacle(c); }

 private:
  const std::uint8_t* data_ = nullptr;
  int width_ = 0;
  int height_ = 0;
  RowOrder order_ = RowOrder::kTopFirst;
  CellInterpretation interpretation_{};
};

}  // namespace eaci
