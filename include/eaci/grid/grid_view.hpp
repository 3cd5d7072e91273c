// Non-owning view of an occupancy grid stored as a row-major byte buffer.
//
// The view can sit on a costmap_2d char map, on the int8 data of a
// nav_msgs/OccupancyGrid or on a map loaded by eaci::io without copying.
// How a byte value maps to free / obstacle is the CellInterpretation's job.
#pragma once

#include <cstddef>
#include <cstdint>

#include "eaci/grid/cell.hpp"

namespace eaci {

enum class UnknownPolicy { kObstacle, kFree };

// Byte value -> traversability. A value equal to `unknown_value` is unknown;
// any other value at or above `obstacle_threshold` is an obstacle.
//   plain 0/1 maps:        threshold 1,   unknown never occurs
//   nav_msgs/OccupancyGrid: threshold 65,  unknown 255 (= int8 -1)
//   costmap_2d:            threshold 253, unknown 255 (NO_INFORMATION)
struct CellInterpretation {
  std::uint8_t obstacle_threshold = 1;
  std::uint8_t unknown_value = 255;
  UnknownPolicy unknown = UnknownPolicy::kObstacle;

  bool isObstacle(std::uint8_t value) const {
    if (value == unknown_value) return unknown == UnknownPolicy::kObstacle;
    return value >= obstacle_threshold;
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

  bool isObstacle(Cell c) const { return interpretation_.isObstacle(value(c)); }
  bool isFree(Cell c) const { return contains(c) && !isObstacle(c); }

 private:
  const std::uint8_t* data_ = nullptr;
  int width_ = 0;
  int height_ = 0;
  RowOrder order_ = RowOrder::kTopFirst;
  CellInterpretation interpretation_{};
};

}  // namespace eaci
