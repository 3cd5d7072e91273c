// Compact free/obstacle grid the planners search, with the move rule.
//
// Built once per plan from a GridView (the only copy a plan makes of the map:
// one byte per cell, next to eight pheromone values per cell).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

class BinaryGrid {
 public:
  BinaryGrid() = default;
  BinaryGrid(int width, int height, bool allow_corner_cutting)
      : width_(width), height_(height), allow_corner_cutting_(allow_corner_cutting),
        blocked_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0) {}

  static BinaryGrid fromView(const GridView& view, bool allow_corner_cutting) {
    BinaryGrid grid(view.width(), view.height(), allow_corner_cutting);
    for (int r = 0; r < view.height(); ++r)
      for (int c = 0; c < view.width(); ++c) grid.setBlocked(Cell{r, c}, view.isObstacle(Cell{r, c}));
    return grid;
  }

  // Rows of 0 (free) / 1 (obstacle), first row = top. Handy for tests and small maps.
  static BinaryGrid fromRows(const std::vector<std::vector<int>>& rows, bool allow_corner_cutting) {
    const int h = static_cast<int>(rows.size());
    const int w = h > 0 ? static_cast<int>(rows[0].size()) : 0;
    BinaryGrid grid(w, h, allow_corner_cutting);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w && c < static_cast<int>(rows[r].size()); ++c) grid.setBlocked(Cell{r, c}, rows[r][c] != 0);
    return grid;
  }

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t cellCount() const { return blocked_.size(); }
  bool allowCornerCutting() const { return allow_corner_cutting_; }

  std::size_t index(Cell c) const {
    return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.col);
  }
  Cell cellAt(std::size_t index) const {
    return Cell{static_cast<int>(index / static_cast<std::size_t>(width_)),
                static_cast<int>(index % static_cast<std::size_t>(width_))};
  }

  bool contains(Cell c) const { return c.row >= 0 && c.col >= 0 && c.row < height_ && c.col < width_; }
  bool isBlocked(Cell c) const { return blocked_[index(c)] != 0; }
  bool isFree(Cell c) const { return contains(c) && blocked_[index(c)] == 0; }
  void setBlocked(Cell c, bool blocked) { blocked_[index(c)] = blocked ? 1 : 0; }

  // The move rule: the target must be free; a diagonal move that would pass
  // between two cells sharing the corner also needs both of them free unless
  // corner cutting is allowed (the paper's benchmark rule).
  bool canMove(Cell from, int dir) const {
    const Cell to = step(from, dir);
    if (!isFree(to)) return false;
    if (!isDiagonal(dir) || allow_corner_cutting_) return true;
    return isFree(Cell{from.row + kDirRow[dir], from.col}) && isFree(Cell{from.row, from.col + kDirCol[dir]});
  }

 private:
  int width_ = 0;
  int height_ = 0;
  bool allow_corner_cutting_ = false;
  std::vector<std::uint8_t> blocked_;
};

}  // namespace eaci
