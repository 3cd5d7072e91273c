// The grid the planners search: per cell an obstacle or a cost 0..254, the move rule, and
// the cost of a move.
//
// Built from a GridView, once per plan (the CLI, the benchmarks) or once per costmap and then
// brought up to date where it changed (the planning service's CostmapMirror): each row carries
// the number of its last change, so what was computed from a grid (landmarks) can be checked
// again where the grid changed only.
#pragma once

#include <array>
#include <atomic>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/end_headings.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// The most cells a grid may have: 2^30 (32768 x 32768, 1 GiB of cell bytes). Cells are
// numbered with 32-bit indices throughout (searches, regions, queues), and UINT32_MAX means
// "none" (ColonyRegion::kNone): staying far below 2^32 keeps every index, and every index plus
// a move's step, clear of that mark and of wrapping round. A plan's buffers on such a map
// already take tens of GiB (11 bytes a cell for a search, more for a colony).
constexpr std::size_t kMaxGridCells = std::size_t{1} << 30;

// "map of W x H cells (N) is larger than the cap of kMaxGridCells cells".
inline std::string gridTooLargeError(long long width, long long height) {
  std::ostringstream e;
  e << "map of " << width << " x " << height << " cells (" << width * height << ") is larger than the cap of "
    << kMaxGridCells << " cells (kMaxGridCells: 32-bit cell indices)";
  return e.str();
}

// What a cell's cost c adds to a move into it, as in global_planner: the move costs
// step_length x (neutral_cost + cost_factor x c) / neutral_cost. With c = 0 a move costs its
// length, so on a binary map a route's cost is its length.
struct CostRule {
  double neutral_cost = 50.0;
  double cost_factor = 3.0;
};

class CostGrid {
 public:
  static constexpr std::uint8_t kObstacle = 255;  // the cell byte of an obstacle; others are costs

  CostGrid() = default;
  // Throws std::invalid_argument for a negative size and std::length_error for one of more
  // than kMaxGridCells cells (eaci::plan refuses those maps before it makes a grid).
  CostGrid(int width, int height, bool allow_corner_cutting, CostRule rule = {}) {
    reset(width, height, allow_corner_cutting, rule);
  }
  // A copy is another grid (its own identity()): what was checked on one is not known of the other.
  CostGrid(const CostGrid& other) { *this = other; }
  CostGrid& operator=(const CostGrid& other) {
    if (this == &other) return *this;
    width_ = other.width_;
    height_ = other.height_;
    allow_corner_cutting_ = other.allow_corner_cutting_;
    cells_ = other.cells_;
    rule_ = other.rule_;
    cell_factor_ = other.cell_factor_;
    row_changes_ = other.row_changes_;
    changes_ = other.changes_;
    identity_ = newIdentity();
    return *this;
  }
  CostGrid(CostGrid&& other) noexcept { *this = std::move(other); }
  CostGrid& operator=(CostGrid&& other) noexcept {
    width_ = other.width_;
    height_ = other.height_;
    allow_corner_cutting_ = other.allow_corner_cutting_;
    cells_ = std::move(other.cells_);
    rule_ = other.rule_;
    cell_factor_ = other.cell_factor_;
    row_changes_ = std::move(other.row_changes_);
    changes_ = other.changes_;
    identity_ = newIdentity();
    other.identity_ = newIdentity();
    return *this;
  }

  // Makes this grid `width` x `height` free cells of cost 0 anew (a new identity), keeping its
  // memory when it is large enough. Throws as the constructor; the grid is unchanged then.
  void reset(int width, int height, bool allow_corner_cutting, CostRule rule = {}) {
    const std::size_t cells = checkedCellCount(width, height);
    setCostRule(rule);
    width_ = width;
    height_ = height;
    allow_corner_cutting_ = allow_corner_cutting;
    cells_.assign(cells, 0);
    row_changes_.assign(static_cast<std::size_t>(height), 0);
    changes_ = 0;
    identity_ = newIdentity();
  }

  // The cell byte (cost 0..254, or kObstacle) of each byte value a view holds: the view's
  // interpretation once per value, then a table look-up per cell.
  static std::array<std::uint8_t, 256> cellByteTable(const CellInterpretation& interpretation) {
    std::array<std::uint8_t, 256> cell_byte{};
    for (int v = 0; v < 256; ++v) {
      const auto value = static_cast<std::uint8_t>(v);
      const std::uint8_t cost = interpretation.cost(value);
      cell_byte[v] = interpretation.isObstacle(value) ? kObstacle : (cost < kObstacle ? cost : kObstacle - 1);
    }
    return cell_byte;
  }

  static CostGrid fromView(const GridView& view, bool allow_corner_cutting, CostRule rule = {}) {
    CostGrid grid(view.width(), view.height(), allow_corner_cutting, rule);
    grid.assignRows(view, 0, view.height());
    return grid;
  }

  // Rows [row_begin, row_end) as `view` (of this grid's size) reads them.
  void assignRows(const GridView& view, int row_begin, int row_end) {
    assignRect(view, cellByteTable(view.interpretation()), row_begin, row_end, 0, width_);
  }
  // Cells [row_begin, row_end) x [col_begin, col_end) as `view` (of this grid's size) reads
  // them through `cell_byte` (cellByteTable of its interpretation). Only a row whose cells
  // changed counts as changed (rowChange). The range must lie on the grid.
  void assignRect(const GridView& view, const std::array<std::uint8_t, 256>& cell_byte, int row_begin, int row_end,
                  int col_begin, int col_end) {
    for (int r = row_begin; r < row_end; ++r) {
      const std::uint8_t* from = view.rowBytes(r);
      std::uint8_t* to = cells_.data() + index(Cell{r, 0});
      std::uint8_t changed = 0;
      for (int c = col_begin; c < col_end; ++c) {
        const std::uint8_t now = cell_byte[from[c]];
        changed |= static_cast<std::uint8_t>(to[c] != now);
        to[c] = now;
      }
      if (changed != 0) markRowChanged(r);
    }
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
  void setBlocked(Cell c, bool blocked) {
    cells_[index(c)] = blocked ? kObstacle : 0;
    markRowChanged(c.row);
  }
  // The cost 0..254 of a free cell.
  std::uint8_t cost(Cell c) const { return cells_[index(c)]; }
  void setCost(Cell c, std::uint8_t cost) {
    cells_[index(c)] = cost < kObstacle ? cost : kObstacle - 1;
    markRowChanged(c.row);
  }

  // Which grid this is: a number no other grid of this process has had (a copy, a moved-to or
  // moved-from grid and a reset() one are other grids).
  std::uint64_t identity() const { return identity_; }
  // The number of the last change to row `row` of this grid (0: none since it was made); every
  // change of a cell raises it above every number the grid gave before.
  std::uint64_t rowChange(int row) const { return row_changes_[static_cast<std::size_t>(row)]; }
  // Throws std::invalid_argument for a rule that would make a move cost less than its length
  // (neutral_cost not > 0, cost_factor < 0, NaN or infinite values) or cost an infinite
  // amount: the octile and landmark bounds of the searches assume no move costs less than its
  // length. The grid keeps its rule then.
  void setCostRule(CostRule rule) {
    std::array<double, kObstacle> factor{};
    factor[0] = 1.0;  // exactly: a move into a cell of cost 0 costs its length
    bool finite = std::isfinite(rule.neutral_cost) && rule.neutral_cost > 0 && std::isfinite(rule.cost_factor) &&
                  rule.cost_factor >= 0;
    for (std::size_t c = 1; finite && c < factor.size(); ++c) {
      factor[c] = (rule.neutral_cost + rule.cost_factor * static_cast<double>(c)) / rule.neutral_cost;
      finite = std::isfinite(factor[c]);
    }
    if (!finite) {
      std::ostringstream e;
      e << "cost rule neutral_cost " << rule.neutral_cost << ", cost_factor " << rule.cost_factor
        << " refused: it needs neutral_cost > 0 and cost_factor >= 0, both finite, so that every move costs at "
           "least its length (and a finite amount)";
      throw std::invalid_argument(e.str());
    }
    rule_ = rule;
    cell_factor_ = factor;
  }

  // The moves out of `from` the move rule (allowedMoves) allows on this grid: bit d for
  // direction d (no bounds checks off the border).
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
  // The same for one move.
  bool canMove(Cell from, int dir) const { return ((movesFrom(from) >> dir) & 1u) != 0; }

  // The cost of an allowed move from `from` in direction `dir`: its length, weighted by the
  // cost of the cell it enters (CostRule). Never less than the move's length.
  double moveCost(Cell from, int dir) const { return moveCostInto(index(step(from, dir)), dir); }
  // The same for the move in direction `dir` that enters the cell of grid index `to_index`.
  double moveCostInto(std::size_t to_index, int dir) const { return stepLength(dir) * cell_factor_[cells_[to_index]]; }

 private:
  static std::uint64_t newIdentity() {
    static std::atomic<std::uint64_t> next{1};
    return next.fetch_add(1, std::memory_order_relaxed);
  }
  void markRowChanged(int row) { row_changes_[static_cast<std::size_t>(row)] = ++changes_; }

  static std::size_t checkedCellCount(int width, int height) {
    if (width < 0 || height < 0)
      throw std::invalid_argument("a grid of " + std::to_string(width) + " x " + std::to_string(height) +
                                  " cells: sizes must not be negative");
    const std::size_t cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (cells > kMaxGridCells) throw std::length_error(gridTooLargeError(width, height));
    return cells;
  }

  int width_ = 0;
  int height_ = 0;
  bool allow_corner_cutting_ = false;
  std::vector<std::uint8_t> cells_;  // cost 0..254, or kObstacle
  CostRule rule_{};
  std::array<double, kObstacle> cell_factor_{};  // (neutral + factor x c) / neutral by cost c
  std::vector<std::uint64_t> row_changes_;       // per row: the number of its last change
  std::uint64_t changes_ = 0;                    // changes numbered so far
  std::uint64_t identity_ = newIdentity();
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

// A route's combined cost (issue #30): its cost (routeCost) plus turn_cost x its heading change
// in radians (routeTurnSteps x kTurnStepRadians), and with end headings the turns onto its first
// move and off its last (endTurnRadians); routeCost itself when turn_cost is 0; +infinity when
// it is not a route.
inline double combinedRouteCost(const CostGrid& grid, const CellPath& route, double turn_cost,
                                const EndHeadings& ends = {}) {
  const double cost = routeCost(grid, route);
  if (turn_cost == 0.0 || !std::isfinite(cost)) return cost;
  return cost + turn_cost * (static_cast<double>(routeTurnSteps(route)) * kTurnStepRadians + endTurnRadians(route, ends));
}

}  // namespace eaci
