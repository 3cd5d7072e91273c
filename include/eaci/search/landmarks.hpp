// Landmarks for the search that meets in the middle (beyond the paper): lower bounds of route
// costs from the triangle inequality, ALT (A*, landmarks, triangle inequality; Goldberg &
// Harrelson, SODA 2005). For a few landmark cells L the cost of a cheapest route from L to
// every cell is kept; a route from a to b then costs at least |d(L, a) - d(L, b)|. On a cost
// map these bounds are much stronger than the octile distance (a route that must go round a
// wall, or through an inflated door, costs far more than its straight line), so the search
// labels far fewer cells. They cost (count + 1) searches of the whole map to make and 4 bytes
// per landmark and cell to keep: worth it only to a planner that plans many times on one
// costmap (the move_base plugin, the planner node), which keeps them in a LandmarkCache.
//
// Costs here are symmetric: a move between cells a and b weighs its length times the smaller
// of the two cells' factors, never more than the move costs either way (a move costs by the
// cell it enters), so d(L, x) bounds routes in both directions. Bounds computed on one grid
// stay lower bounds, and consistent, on every grid whose cells are all at least as costly (an
// obstacle counts as the costliest): Landmarks::holdsFor checks that.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "eaci/grid/cell_window.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/window_moves.hpp"
#include "eaci/search/bucket_queue.hpp"

namespace eaci {

// Landmark tables take 4 bytes per landmark and cell; no more than this is made (256 MiB, e.g.
// 16 landmarks on 2048 x 2048 cells, 1 on 8192 x 8192). Making them also needs 17 bytes per
// cell of scratch while it runs, whatever the count.
constexpr std::size_t kMaxLandmarkBytes = std::size_t{256} << 20;

// How many of `requested` landmarks fit in kMaxLandmarkBytes on a map of `cells` cells (0 if
// not even one does).
inline int landmarksThatFit(std::size_t cells, int requested) {
  if (requested <= 0) return 0;
  if (cells == 0) return requested;
  const std::size_t fit = kMaxLandmarkBytes / (cells * sizeof(float));
  return static_cast<int>(std::min(fit, static_cast<std::size_t>(requested)));
}

// Making landmarks may be cancelled (LandmarkCache: a change of map size, the cache destroyed):
// every loop over the map's cells asks the flag once per kCancelPollCells cells (a relaxed
// atomic load per 64 Ki cells costs nothing beside them) and the searches once per 4096 cells
// they take, so a cancelled making ends within some 100 microseconds of the thread running.
constexpr std::size_t kCancelPollCells = std::size_t{1} << 16;
inline bool landmarksCancelled(const std::atomic<bool>* cancel) {
  return cancel != nullptr && cancel->load(std::memory_order_relaxed);
}
// Calls `chunk(begin, end)` over the cells [0, cells) in pieces of kCancelPollCells, asking
// `cancel` before each piece: false, the rest not done, once it is set.
template <class Chunk>
bool forCellChunks(std::size_t cells, const std::atomic<bool>* cancel, Chunk&& chunk) {
  for (std::size_t begin = 0; begin < cells; begin += kCancelPollCells) {
    if (landmarksCancelled(cancel)) return false;
    chunk(begin, std::min(cells, begin + kCancelPollCells));
  }
  return true;
}

// What landmarks depend on besides the cells' costs: a grid's size, move rule and cost rule.
struct GridShape {
  int width = 0, height = 0;
  bool corner_cutting = false;
  double neutral_cost = 0.0, cost_factor = 0.0;
  static GridShape of(const CostGrid& g) {
    return {g.width(), g.height(), g.allowCornerCutting(), g.costRule().neutral_cost, g.costRule().cost_factor};
  }
  bool operator==(const GridShape& o) const {
    return width == o.width && height == o.height && corner_cutting == o.corner_cutting &&
           neutral_cost == o.neutral_cost && cost_factor == o.cost_factor;
  }
};

class Landmarks {
 public:
  // `count` landmarks on `grid` by farthest selection: the first is the cell farthest from a
  // free cell near the middle of the free cells, each next one the cell farthest from all
  // chosen so far, all in that cell's connected part of the map. Null when `cancel` became true
  // on the way, or the grid has no free cell; none (count() 0) where route costs are too large
  // for floats to bound them usefully. `count` is cut to landmarksThatFit (0: null).
  static std::shared_ptr<const Landmarks> compute(const CostGrid& grid, int count,
                                                  const std::atomic<bool>* cancel = nullptr) {
    count = landmarksThatFit(grid.cellCount(), count);
    if (count <= 0 || landmarksCancelled(cancel)) return nullptr;
    const std::size_t cells_in_grid = grid.cellCount();
    const std::uint8_t* cells = grid.cellBytes();
    std::size_t free_count = 0;
    if (!forCellChunks(cells_in_grid, cancel, [&](std::size_t begin, std::size_t end) {
          for (std::size_t i = begin; i < end; ++i) free_count += cells[i] != CostGrid::kObstacle;
        }))
      return nullptr;
    if (free_count == 0) return nullptr;
    std::size_t seed = 0;
    for (std::size_t i = 0, seen = 0; i < cells_in_grid; ++i) {
      if ((i % kCancelPollCells) == 0 && landmarksCancelled(cancel)) return nullptr;
      if (cells[i] != CostGrid::kObstacle && seen++ == free_count / 2) {
        seed = i;
        break;
      }
    }
    auto landmarks = std::shared_ptr<Landmarks>(new Landmarks(grid));  // a copy of the cells: a memcpy
    if (landmarksCancelled(cancel)) return nullptr;
    std::vector<double> distance(cells_in_grid);
    std::vector<double> nearest_landmark(cells_in_grid, std::numeric_limits<double>::infinity());
    detail::BucketQueue<> open;
    if (!symmetricCosts(grid, seed, distance, open, cancel)) return nullptr;
    if (!farthest(distance, seed, cancel)) return nullptr;
    landmarks->count_ = count;
    landmarks->distance_.assign(cells_in_grid * static_cast<std::size_t>(count), kUnreached);
    double largest = 0.0;
    for (int k = 0; k < count; ++k) {
      if (!symmetricCosts(grid, seed, distance, open, cancel)) return nullptr;
      if (!forCellChunks(cells_in_grid, cancel, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
              if (!std::isfinite(distance[i])) continue;
              landmarks->distance_[i * static_cast<std::size_t>(count) + static_cast<std::size_t>(k)] =
                  static_cast<float>(distance[i]);
              largest = std::max(largest, distance[i]);
              nearest_landmark[i] = std::min(nearest_landmark[i], distance[i]);
            }
          }))
        return nullptr;
      if (!farthest(nearest_landmark, seed, cancel)) return nullptr;
    }
    // As floats, each distance is off by at most largest x 2^-24, and so is the difference of
    // two; a bound is then off by at most 3 x that, and shrinking every bound by a factor
    // 1 - 8 x that keeps them consistent (no move costs less than 1).
    // Distances too large for floats to bound usefully: landmarks that bound nothing (count 0),
    // so that the grid is not tried again.
    const double rounding = largest * std::ldexp(1.0, -24);
    if (8.0 * rounding >= 0.5) {
      landmarks->count_ = 0;
      landmarks->distance_.clear();
      return landmarks;
    }
    landmarks->shrink_ = 1.0 - 8.0 * rounding;
    return landmarks;
  }

  int count() const { return count_; }

  // Grids of the same size, move rule and cost rule: their cells can be compared one by one.
  static bool sameShape(const CostGrid& a, const CostGrid& b) { return GridShape::of(a) == GridShape::of(b); }

  // True when the bounds hold on `grid`: the same shape, and no cell cheaper than on the grid
  // they were made on (or free where it was an obstacle).
  bool holdsFor(const CostGrid& grid) const {
    if (!sameShape(grid, floor_)) return false;
    return !cheaperCells(grid, 0, grid.cellCount());
  }
  // Some cell of row `row` of `grid` (of the same shape) is cheaper than on their grid.
  bool cheaperRow(const CostGrid& grid, int row) const {
    const std::size_t begin = grid.index(Cell{row, 0});
    return cheaperCells(grid, begin, begin + static_cast<std::size_t>(grid.width()));
  }

  // The grid they were made on.
  const CostGrid& grid() const { return floor_; }

 private:
  bool cheaperCells(const CostGrid& grid, std::size_t begin, std::size_t end) const {
    const std::uint8_t* now = grid.cellBytes();
    const std::uint8_t* then = floor_.cellBytes();
    std::uint8_t cheaper = 0;  // no early exit: the loop vectorises
    for (std::size_t i = begin; i < end; ++i) cheaper |= static_cast<std::uint8_t>(now[i] < then[i]);
    return cheaper != 0;
  }

 public:

  // A lower bound of the cost of every route between two grid cells, either way, from their
  // landmark costs (of()); 0 where no landmark reaches both.
  double lowerBound(const float* a, const float* b) const {
    double bound = 0.0, same = 0.0;
    lowerBounds(a, b, b, bound, same);
    return bound;
  }
  // Both bounds of one cell at once: from cell `c` to `a` and to `b` (landmark distances of each).
  void lowerBounds(const float* c, const float* a, const float* b, double& to_a, double& to_b) const {
    float bound_a = 0.0f, bound_b = 0.0f;
    for (int k = 0; k < count_; ++k) {  // NaN (unreached) loses every std::max
      bound_a = std::max(bound_a, std::abs(c[k] - a[k]));
      bound_b = std::max(bound_b, std::abs(c[k] - b[k]));
    }
    to_a = static_cast<double>(bound_a) * shrink_;
    to_b = static_cast<double>(bound_b) * shrink_;
  }
  // Some landmark reaches the cell whose landmark distances (of()) these are: it lies in the
  // part of the map the landmarks were chosen in (every landmark reaches it then).
  bool reaches(const float* c) const {
    for (int k = 0; k < count_; ++k)
      if (!std::isnan(c[k])) return true;
    return false;
  }
  // The `count()` landmark distances of grid cell `index`.
  const float* of(std::size_t index) const { return distance_.data() + index * static_cast<std::size_t>(count_); }

 private:
  // Unreached: every difference with it is NaN, which std::max(bound, NaN) passes over.
  static constexpr float kUnreached = std::numeric_limits<float>::quiet_NaN();

  explicit Landmarks(const CostGrid& grid) : floor_(grid) {}

  // Costs of cheapest routes from `source` over the symmetric move costs, +infinity where
  // unreached; false when cancelled.
  static bool symmetricCosts(const CostGrid& grid, std::size_t source, std::vector<double>& distance,
                             detail::BucketQueue<>& open, const std::atomic<bool>* cancel) {
    if (!forCellChunks(distance.size(), cancel, [&](std::size_t begin, std::size_t end) {
          std::fill(distance.begin() + static_cast<std::ptrdiff_t>(begin),
                    distance.begin() + static_cast<std::ptrdiff_t>(end), std::numeric_limits<double>::infinity());
        }))
      return false;
    distance[source] = 0.0;
    open.clear();
    open.push(0.0, detail::BucketEntry{0.0, static_cast<std::uint32_t>(source)});
    const auto stale = [&distance](const detail::BucketEntry& e) { return e.cost > distance[e.slot]; };
    const CellWindow whole = CellWindow::whole(grid);
    const WindowMoves moves_in(grid, whole);
    detail::BucketEntry top;
    for (std::size_t n = 0; open.pop(top, stale); ++n) {
      if ((n & 4095) == 0 && cancel != nullptr && cancel->load(std::memory_order_relaxed)) return false;
      const Cell here = grid.cellAt(top.slot);
      for (unsigned moves = moves_in.from(here); moves != 0; moves &= moves - 1) {
        const int d = __builtin_ctz(moves);
        const std::size_t j = grid.index(step(here, d));
        const double g = top.cost + std::min(grid.moveCostInto(j, d), grid.moveCostInto(top.slot, d));
        if (g >= distance[j]) continue;
        distance[j] = g;
        open.push(g, detail::BucketEntry{g, static_cast<std::uint32_t>(j)});
      }
    }
    return true;
  }

  // Sets `best` (in: the fallback) to the reached cell of largest `distance` (the lowest index
  // on ties), unchanged if none; false when cancelled.
  static bool farthest(const std::vector<double>& distance, std::size_t& best, const std::atomic<bool>* cancel) {
    return forCellChunks(distance.size(), cancel, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        if (std::isfinite(distance[i]) && distance[i] > distance[best]) best = i;
    });
  }

  CostGrid floor_;               // the grid the distances were computed on
  int count_ = 0;
  std::vector<float> distance_;  // [cell * count_ + k]: cost between landmark k and the cell; kUnreached
  double shrink_ = 1.0;          // every bound is multiplied by it (float rounding)
};
}  // namespace eaci
