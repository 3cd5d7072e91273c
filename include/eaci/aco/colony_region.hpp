// The cells an ant colony works on (beyond the paper): the whole map (classic ACO, the paper's
// islands), or the cells within a margin of a cheapest route (geodesic islands), so that the
// pheromone, the ants' taboo lists and the heuristic tables grow with the route, not the map.
//
// Region cells are numbered 0 .. size() - 1 (in grid index order); pheromone, visit marks and
// per-cell tables are indexed by that number. On the whole map the number is the grid index.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/grid/cell_window.hpp"
#include "eaci/grid/sparse_cell_map.hpp"

namespace eaci {

class ColonyRegion {
 public:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  ColonyRegion() = default;

  // Every cell of the map; a move is allowed where CostGrid::canMove allows it. `reuse`: a
  // region whose memory the new one takes over (a planner keeps one between plans). `stop`:
  // ticked once per row of cells; stopped, the region is unfinished (the caller reads
  // stop->stopped() and drops it).
  static ColonyRegion wholeMap(const CostGrid& grid) { return wholeMap(grid, ColonyRegion()); }
  static ColonyRegion wholeMap(const CostGrid& grid, ColonyRegion reuse, StopPoll* stop = nullptr) {
    ColonyRegion region = std::move(reuse);
    region.clear();
    region.whole_map_ = true;
    region.grid_cells_ = grid.cellCount();
    region.grid_width_ = grid.width();
    region.size_ = grid.cellCount();
    for (int d = 0; d < kDirections; ++d)
      region.index_step_[d] = static_cast<std::ptrdiff_t>(kDirRow[d]) * grid.width() + kDirCol[d];
    region.moves_.assign(grid.cellCount(), 0);
    StopPoll never;
    StopPoll& poll = stop != nullptr ? *stop : never;
    for (int row = 0; row < grid.height(); ++row) {
      if (poll.tick(static_cast<std::size_t>(grid.width()))) return region;
      for (int col = 0; col < grid.width(); ++col)
        region.moves_[grid.index(Cell{row, col})] = static_cast<std::uint8_t>(grid.movesFrom(Cell{row, col}));
    }
    return region;
  }

  // The free cells at most `margin` moves (CostGrid::canMove) from a cell of `route`; a move
  // is allowed where the grid allows it and both cells are in the region.
  // `max_cells`: a region that would hold more cells is not made: it comes back empty with
  // tooLarge() true (the caller's pheromone would not fit; kMaxPheromoneBytes). `stop`:
  // ticked once per cell; stopped, the region is unfinished (the caller reads stop->stopped()).
  static ColonyRegion aroundRoute(const CostGrid& grid, const CellPath& route, int margin) {
    return aroundRoute(grid, route, margin, ColonyRegion());
  }
  static ColonyRegion aroundRoute(const CostGrid& grid, const CellPath& route, int margin, ColonyRegion reuse,
                                  std::size_t max_cells = std::numeric_limits<std::size_t>::max(),
                                  StopPoll* stop = nullptr) {
    StopPoll never;
    StopPoll& poll = stop != nullptr ? *stop : never;
    ColonyRegion region = std::move(reuse);
    region.clear();
    region.grid_cells_ = grid.cellCount();
    region.grid_width_ = grid.width();
    // Every region cell lies within `margin` of the route's bounding box: the map-to-region
    // numbering covers that box, in blocks made only where the region is (SparseCellMap), so
    // neither a short route nor one across the map costs a pass over the map or the box.
    region.region_of_cell_.reset(route.empty() ? CellWindow{} : CellWindow::around(grid, route, margin));
    const auto mark = [&region](Cell c) -> std::uint32_t& { return region.region_of_cell_.at(c); };
    const auto marked = [&region](Cell c) { return region.region_of_cell_.get(c) != kNone; };
    // Breadth first from the route, one ring of moves at a time; marks cells with 0 on entry.
    std::vector<std::uint32_t>& ring = region.ring_;
    std::vector<std::uint32_t>& next_ring = region.next_ring_;
    for (const Cell& c : route) {
      if (!grid.isFree(c)) continue;
      if (!marked(c)) {
        mark(c) = 0;
        region.grid_index_.push_back(static_cast<std::uint32_t>(grid.index(c)));
        ring.push_back(static_cast<std::uint32_t>(grid.index(c)));
      }
    }
    const auto refuse = [&region] {  // over max_cells: no region
      region.clear();
      region.too_large_ = true;
      return std::move(region);
    };
    if (region.grid_index_.size() > max_cells) return refuse();
    for (int distance = 1; distance <= margin && !ring.empty(); ++distance) {
      next_ring.clear();
      for (std::uint32_t i : ring) {
        if (poll.tick()) return region;
        if (region.grid_index_.size() > max_cells) return refuse();
        const Cell here = grid.cellAt(i);
        for (unsigned moves = grid.movesFrom(here); moves != 0; moves &= moves - 1) {
          const Cell next = step(here, __builtin_ctz(moves));
          if (marked(next)) continue;
          mark(next) = 0;
          const auto j = static_cast<std::uint32_t>(grid.index(next));
          region.grid_index_.push_back(j);
          next_ring.push_back(j);
        }
      }
      ring.swap(next_ring);
    }
    if (region.grid_index_.size() > max_cells) return refuse();
    sortIndices(region.grid_index_, ring);
    region.size_ = region.grid_index_.size();
    for (std::size_t r = 0; r < region.size_; ++r) mark(grid.cellAt(region.grid_index_[r])) = static_cast<std::uint32_t>(r);
    // The neighbours, by the region's order (grid index order): the cells of the row above and
    // of the row below are found by two cursors into grid_index_ that only move forward.
    region.neighbours_.assign(region.size_ * kDirections, kNone);
    region.moves_.assign(region.size_, 0);
    const std::vector<std::uint32_t>& index = region.grid_index_;
    const auto width = static_cast<std::int64_t>(grid.width());
    std::size_t above = 0, below = 0;
    // The region numbers of the cells `first`, `first` + 1, `first` + 2 (kNone for those not in
    // the region) from `cursor` on, which is moved to the first region cell at or after `first`.
    const auto threeFrom = [&index](std::size_t& cursor, std::int64_t first, std::uint32_t (&found)[3]) {
      while (cursor < index.size() && static_cast<std::int64_t>(index[cursor]) < first) ++cursor;
      std::size_t at = cursor;
      for (int k = 0; k < 3; ++k) {
        found[k] = kNone;
        if (at < index.size() && static_cast<std::int64_t>(index[at]) == first + k) found[k] = static_cast<std::uint32_t>(at++);
      }
    };
    for (std::size_t r = 0; r < region.size_; ++r) {
      if (poll.tick()) return region;
      const auto here_index = static_cast<std::int64_t>(index[r]);
      std::uint32_t up[3], down[3];  // columns col - 1, col, col + 1
      threeFrom(above, here_index - width - 1, up);
      threeFrom(below, here_index + width - 1, down);
      static_assert(kDirRow[1] == -1 && kDirCol[1] == 1 && kDirRow[3] == -1 && kDirCol[3] == -1 && kDirRow[5] == 1 &&
                        kDirCol[5] == -1 && kDirRow[7] == 1 && kDirCol[7] == 1 && kDirCol[0] == 1 && kDirCol[4] == -1,
                    "the directions as along[] lists them: E, NE, N, NW, W, SW, S, SE");
      std::uint32_t along[kDirections];
      along[0] = r + 1 < region.size_ && index[r + 1] == index[r] + 1 ? static_cast<std::uint32_t>(r + 1) : kNone;
      along[1] = up[2];
      along[2] = up[1];
      along[3] = up[0];
      along[4] = r > 0 && index[r - 1] + 1 == index[r] ? static_cast<std::uint32_t>(r - 1) : kNone;
      along[5] = down[0];
      along[6] = down[1];
      along[7] = down[2];
      for (unsigned moves = grid.movesFrom(grid.cellAt(index[r])); moves != 0; moves &= moves - 1) {
        const int d = __builtin_ctz(moves);  // an allowed move stays on the map: no wrap round a row
        region.neighbours_[r * kDirections + static_cast<std::size_t>(d)] = along[d];
        if (along[d] != kNone) region.moves_[r] |= static_cast<std::uint8_t>(1u << d);
      }
    }
    return region;
  }

  std::size_t size() const { return size_; }            // region cells
  std::size_t gridCellCount() const { return grid_cells_; }
  // aroundRoute refused it: it would have held more than its max_cells (the region is empty).
  bool tooLarge() const { return too_large_; }

  // Grid index of region cell r.
  std::uint32_t gridIndex(std::uint32_t r) const { return whole_map_ ? r : grid_index_[r]; }
  // Region number of a grid cell, kNone outside the region.
  std::uint32_t regionIndex(std::size_t grid_index) const {
    if (whole_map_) return static_cast<std::uint32_t>(grid_index);
    const auto width = static_cast<std::size_t>(grid_width_);
    return regionIndex(Cell{static_cast<int>(grid_index / width), static_cast<int>(grid_index % width)});
  }
  // The same for a cell of the grid.
  std::uint32_t regionIndex(Cell c) const {
    if (whole_map_) return static_cast<std::uint32_t>(static_cast<std::size_t>(c.row) * static_cast<std::size_t>(grid_width_) + static_cast<std::size_t>(c.col));
    return region_of_cell_.get(c);
  }

  // The moves out of region cell r that stay in the region: bit d for direction d.
  std::uint8_t moves(std::uint32_t r) const { return moves_[r]; }
  // The region cell one move in direction `dir` from region cell r, for a move moves(r) allows.
  std::uint32_t neighbourAlong(std::uint32_t r, int dir) const {
    if (!whole_map_) return neighbours_[static_cast<std::size_t>(r) * kDirections + static_cast<std::size_t>(dir)];
    return static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(r) + index_step_[dir]);
  }
  // The same for any move: kNone when it is not allowed or leaves the region.
  std::uint32_t neighbour(std::uint32_t r, int dir) const {
    return (moves_[r] & (1u << dir)) ? neighbourAlong(r, dir) : kNone;
  }

 private:
  // Empty, with the memory it holds kept for the next region.
  void clear() {
    whole_map_ = false;
    too_large_ = false;
    grid_cells_ = size_ = 0;
    grid_width_ = 0;
    region_of_cell_.reset(CellWindow{});
    for (auto* v : {&grid_index_, &neighbours_, &ring_, &next_ring_}) v->clear();
    moves_.clear();
  }

  // Sorts `values` ascending: three passes of a radix sort on 11 bits each (`scratch` is used).
  static void sortIndices(std::vector<std::uint32_t>& values, std::vector<std::uint32_t>& scratch) {
    constexpr int kBits = 11;
    constexpr std::uint32_t kBuckets = 1u << kBits;
    scratch.resize(values.size());
    std::vector<std::uint32_t> count(kBuckets);
    for (int shift = 0; shift < 32; shift += kBits) {
      std::fill(count.begin(), count.end(), 0u);
      for (std::uint32_t v : values) ++count[(v >> shift) & (kBuckets - 1)];
      std::uint32_t total = 0;
      for (std::uint32_t& c : count) {
        const std::uint32_t here = c;
        c = total;
        total += here;
      }
      for (std::uint32_t v : values) scratch[count[(v >> shift) & (kBuckets - 1)]++] = v;
      values.swap(scratch);
    }
  }

  bool whole_map_ = false;
  bool too_large_ = false;
  std::size_t grid_cells_ = 0;
  std::size_t size_ = 0;
  std::vector<std::uint8_t> moves_;  // per region cell: bit d when the move in direction d is allowed and stays inside
  // Whole map: the index step of each move.
  std::array<std::ptrdiff_t, kDirections> index_step_{};
  // Around a route: grid index per region cell, region number per cell of the route's bounding
  // box grown by the margin (kNone elsewhere), neighbours.
  std::vector<std::uint32_t> grid_index_;
  int grid_width_ = 0;
  SparseCellMap region_of_cell_;
  std::vector<std::uint32_t> neighbours_;  // [r * kDirections + d]
  std::vector<std::uint32_t> ring_, next_ring_;  // aroundRoute's rings of cells (and sort scratch)
};

}  // namespace eaci
