// The grid the planners search: per cell an obstacle or a cost 0..254, the move rule, and
// the cost of a move.
//
// Built once per plan from a GridView (the only copy a plan makes of the map: one byte per
// cell, next to eight pheromone values per cell).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// What a cell's cost c adds to a move into it, as in global_planner: the move costs
// step_length x (neutral_cost + cost_factor x c) / neutral_cost. With c = 0 a move costs its
// length, so on a binary map a route's cost is its length.
struct CostRule {
  double neutral_cost = 50.0;
  double cost_factor = 3.0;
};

// The moves the rule allows (bit d: direction d, as CostGrid::canMove) given which neighbours
// are free (bit d: the neighbour in direction d). Without corner cutting a diagonal also needs
// the two straight neighbours beside it, directions d - 1 and d + 1.
inline unsigned allowedMoves(unsigned free_neighbours, bool allow_corner_cutting) {
  if (allow_corner_cutting) return free_neighbours;
  const unsigned straight = free_neighbours & 0x55u;
  const unsigned from_before = ((straight << 1) | (straight >> 7)) & 0xFFu;  // bit d - 1 moved to d
  const unsigned from_after = ((straight >> 1) | (straight << 7)) & 0xFFu;   // bit d + 1 moved to d
  return straight | (free_neighbours & 0xAAu & from_before & from_after);
}

class CostGrid {
 public:
  static constexpr std::uint8_t kObstacle = 255;  // the cell byte of an obstacle; others are costs

  CostGrid() = default;
  CostGrid(int width, int height, bool allow_corner_cutting, CostRule rule = {})
      : width_(width), height_(height), allow_corner_cutting_(allow_corner_cutting),
        cells_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0) {
    setCostRule(rule);
  }

  static CostGrid fromView(const GridView& view, bool allow_corner_cutting, CostRule rule = {}) {
    CostGrid grid(view.width(), view.height(), allow_corner_cutting, rule);
    // The interpretation once per byte value, then a table look-up per cell (a plan converts
    // the whole costmap: 1.4 million cells on a building map).
    std::array<std::uint8_t, 256> cell_byte{};
    for (int v = 0; v < 256; ++v) {
      const auto value = static_cast<std::uint8_t>(v);
      const std::uint8_t cost = view.interpretation().cost(value);
      cell_byte[v] = view.interpretation().isObstacle(value) ? kObstacle : (cost < kObstacle ? cost : kObstacle - 1);
    }
    for (int r = 0; r < view.height(); ++r) {
      const std::uint8_t* from = view.rowBytes(r);
      std::uint8_t* to = grid.cells_.data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(view.width());
      for (int c = 0; c < view.width(); ++c) to[c] = cell_byte[from[c]];
    }
    return grid;
  }

  // Rows of 0 (free) / 1 (obstacle), first row = top. Handy for tests and small maps.
  static CostGrid fromRows(const std::vector<std::vector<int>>& rows, bool allow_corner_cutting) {
    const int h = static_cast<int>(rows.size());
    const int w = h > 0 ? static_cast<int>(rows[0].size()) : 0;
    CostGrid grid(w, h, allow_corner_cutting);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w && c < static_cast<int>(rows[r].size()); ++c) grid.setBlocked(Cell{r, c}, rows[r][c] != 0);
    return grid;
  }

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t cellCount() const { return cells_.size(); }
  bool allowCornerCutting() const { return allow_corner_cutting_; }
  const CostRule& costRule() const { return rule_; }
  // The cell bytes in index order (cost 0..254, or kObstacle), for loops that read many.
  const std::uint8_t* cellBytes() const { return cells_.data(); }

  std::size_t index(Cell c) const {
    return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.col);
  }
  Cell cellAt(std::size_t index) const {
    return Cell{static_cast<int>(index / static_cast<std::size_t>(width_)),
                static_cast<int>(index % static_cast<std::size_t>(width_))};
  }

  bool contains(Cell c) const { return c.row >= 0 && c.col >= 0 && c.row < height_ && c.col < width_; }
  bool isBlocked(Cell c) const { return cells_[index(c)] == kObstacle; }
  bool isFree(Cell c) const { return contains(c) && cells_[index(c)] != kObstacle; }
  void setBlocked(Cell c, bool blocked) { cells_[index(c)] = blocked ? kObstacle : 0; }
  // The cost 0..254 of a free cell.
  std::uint8_t cost(Cell c) const { return cells_[index(c)]; }
  void setCost(Cell c, std::uint8_t cost) { cells_[index(c)] = cost < kObstacle ? cost : kObstacle - 1; }
  void setCostRule(CostRule rule) {
    rule_ = rule;
    cell_factor_[0] = 1.0;  // exactly: a move into a cell of cost 0 costs its length
    for (std::size_t c = 1; c < cell_factor_.size(); ++c)
      cell_factor_[c] = (rule.neutral_cost + rule.cost_factor * static_cast<double>(c)) / rule.neutral_cost;
  }

  // The move rule: the target must be free; a diagonal move that would pass
  // between two cells sharing the corner also needs both of them free unless
  // corner cutting is allowed (the paper's benchmark rule).
  bool canMove(Cell from, int dir) const {
    const Cell to = step(from, dir);
    if (!isFree(to)) return false;
    if (!isDiagonal(dir) || allow_corner_cutting_) return true;
    return isFree(Cell{from.row + kDirRow[dir], from.col}) && isFree(Cell{from.row, from.col + kDirCol[dir]});
  }

  // Bit d: canMove(from, d), for all eight directions at once (no bounds checks off the border).
  unsigned movesFrom(Cell from) const {
    unsigned free_neighbours = 0;
    if (from.row > 0 && from.col > 0 && from.row + 1 < height_ && from.col + 1 < width_) {
      const std::uint8_t* here = cells_.data() + index(from);
      for (int d = 0; d < kDirections; ++d)
        free_neighbours |= static_cast<unsigned>(here[kDirRow[d] * width_ + kDirCol[d]] != kObstacle) << d;
    } else {
      for (int d = 0; d < kDirections; ++d) free_neighbours |= static_cast<unsigned>(isFree(step(from, d))) << d;
    }
    return allowedMoves(free_neighbours, allow_corner_cutting_);
  }

  // The cost of an allowed move from `from` in direction `dir`: its length, weighted by the
  // cost of the cell it enters (CostRule). Never less than the move's length.
  double moveCost(Cell from, int dir) const { return moveCostInto(index(step(from, dir)), dir); }
  // The same for the move in direction `dir` that enters the cell of grid index `to_index`.
  double moveCostInto(std::size_t to_index, int dir) const { return stepLength(dir) * cell_factor_[cells_[to_index]]; }

 private:
  int width_ = 0;
  int height_ = 0;
  bool allow_corner_cutting_ = false;
  std::vector<std::uint8_t> cells_;  // cost 0..254, or kObstacle
  CostRule rule_{};
  std::array<double, kObstacle> cell_factor_{};  // (neutral + factor x c) / neutral by cost c
};

// A route's cost: the sum of its moves' costs (0 for a single cell); +infinity when two
// consecutive cells are not 8-neighbours (not a route).
inline double routeCost(const CostGrid& grid, const CellPath& route) {
  double cost = 0.0;
  for (std::size_t k = 1; k < route.size(); ++k) {
    const int dir = directionBetween(route[k - 1], route[k]);
    if (dir < 0) return std::numeric_limits<double>::infinity();
    cost += grid.moveCost(route[k - 1], dir);
  }
  return cost;
}

}  // namespace eaci
