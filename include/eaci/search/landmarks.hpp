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
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/worker_group.hpp"
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
    if (count <= 0) return nullptr;
    auto landmarks = std::shared_ptr<Landmarks>(new Landmarks(grid));
    const std::uint8_t* cells = grid.cellBytes();
    std::size_t free_count = 0;
    for (std::size_t i = 0; i < grid.cellCount(); ++i) free_count += cells[i] != CostGrid::kObstacle;
    if (free_count == 0 || count <= 0) return nullptr;
    std::size_t seed = 0;
    for (std::size_t i = 0, seen = 0; i < grid.cellCount(); ++i)
      if (cells[i] != CostGrid::kObstacle && seen++ == free_count / 2) {
        seed = i;
        break;
      }
    std::vector<double> distance(grid.cellCount());
    std::vector<double> nearest_landmark(grid.cellCount(), std::numeric_limits<double>::infinity());
    detail::BucketQueue open;
    if (!symmetricCosts(grid, seed, distance, open, cancel)) return nullptr;
    seed = farthest(distance, seed);
    landmarks->count_ = count;
    landmarks->distance_.assign(grid.cellCount() * static_cast<std::size_t>(count), kUnreached);
    double largest = 0.0;
    for (int k = 0; k < count; ++k) {
      if (!symmetricCosts(grid, seed, distance, open, cancel)) return nullptr;
      for (std::size_t i = 0; i < distance.size(); ++i) {
        if (!std::isfinite(distance[i])) continue;
        landmarks->distance_[i * static_cast<std::size_t>(count) + static_cast<std::size_t>(k)] = static_cast<float>(distance[i]);
        largest = std::max(largest, distance[i]);
        nearest_landmark[i] = std::min(nearest_landmark[i], distance[i]);
      }
      seed = farthest(nearest_landmark, seed);
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
  static bool sameShape(const CostGrid& a, const CostGrid& b) {
    return a.width() == b.width() && a.height() == b.height() && a.allowCornerCutting() == b.allowCornerCutting() &&
           a.costRule().neutral_cost == b.costRule().neutral_cost && a.costRule().cost_factor == b.costRule().cost_factor;
  }

  // True when the bounds hold on `grid`: the same shape, and no cell cheaper than on the grid
  // they were made on (or free where it was an obstacle).
  bool holdsFor(const CostGrid& grid) const {
    if (!sameShape(grid, floor_)) return false;
    const std::uint8_t* now = grid.cellBytes();
    const std::uint8_t* then = floor_.cellBytes();
    std::uint8_t cheaper = 0;  // no early exit: the loop vectorises
    for (std::size_t i = 0; i < grid.cellCount(); ++i) cheaper |= static_cast<std::uint8_t>(now[i] < then[i]);
    return cheaper == 0;
  }

  // The grid they were made on.
  const CostGrid& grid() const { return floor_; }

  // A lower bound of the cost of every route between grid cells a and b, either way (0 where
  // no landmark reaches both).
  double lowerBound(std::size_t a, std::size_t b) const { return lowerBound(of(a), of(b)); }
  // The same from the landmark distances of the two cells (of()).
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
  // The `count()` landmark distances of grid cell `index`.
  const float* of(std::size_t index) const { return distance_.data() + index * static_cast<std::size_t>(count_); }

 private:
  // Unreached: every difference with it is NaN, which std::max(bound, NaN) passes over.
  static constexpr float kUnreached = std::numeric_limits<float>::quiet_NaN();

  explicit Landmarks(const CostGrid& grid) : floor_(grid) {}

  // Costs of cheapest routes from `source` over the symmetric move costs, +infinity where
  // unreached; false when cancelled.
  static bool symmetricCosts(const CostGrid& grid, std::size_t source, std::vector<double>& distance,
                             detail::BucketQueue& open, const std::atomic<bool>* cancel) {
    std::fill(distance.begin(), distance.end(), std::numeric_limits<double>::infinity());
    distance[source] = 0.0;
    open.clear();
    open.push(0.0, detail::BucketEntry{0.0, static_cast<std::uint32_t>(source)});
    const auto stale = [&distance](const detail::BucketEntry& e) { return e.cost > distance[e.slot]; };
    detail::BucketEntry top;
    for (std::size_t n = 0; open.pop(top, stale); ++n) {
      if ((n & 4095) == 0 && cancel != nullptr && cancel->load(std::memory_order_relaxed)) return false;
      const Cell here = grid.cellAt(top.slot);
      for (unsigned moves = grid.movesFrom(here); moves != 0; moves &= moves - 1) {
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

  // The reached cell of largest `distance` (the lowest index on ties); `fallback` if none.
  static std::size_t farthest(const std::vector<double>& distance, std::size_t fallback) {
    std::size_t best = fallback;
    for (std::size_t i = 0; i < distance.size(); ++i)
      if (std::isfinite(distance[i]) && distance[i] > distance[best]) best = i;
    return best;
  }

  CostGrid floor_;               // the grid the distances were computed on
  int count_ = 0;
  std::vector<float> distance_;  // [cell * count_ + k]: cost between landmark k and the cell; kUnreached
  double shrink_ = 1.0;          // every bound is multiplied by it (float rounding)
};

// Landmarks kept for a planner that plans again and again, made in the background: the first
// plan on a costmap asks, finds none, and starts a thread that makes them; later plans on that
// costmap, or on one no cell of which is cheaper, use them. When the costmap gets cheaper
// somewhere (an obstacle cleared), new ones are made on the cell-wise cheapest of the old and
// the new costmap, so that they hold for both, and costmaps that come and go between the two
// do not make them again each time. Plans that find none ready search with octile bounds alone:
// the same costs, though among equally cheap routes they may pick another.
// Nothing here reaches the plan as an exception: a failure while making them (std::bad_alloc,
// anything) or a thread that cannot start leaves the cache without new landmarks, says why
// (lastError()), and the next plan that asks tries again.
class LandmarkCache {
 public:
  // Makes landmarks (Landmarks::compute); replaceable for tests that make it fail.
  using Maker = std::function<std::shared_ptr<const Landmarks>(const CostGrid&, int count, const std::atomic<bool>* cancel)>;

  // `count` landmarks asked for (cut to landmarksThatFit for each map). `make`, `start`: how
  // they are made and their thread started (empty: Landmarks::compute, std::thread).
  explicit LandmarkCache(int count, Maker make = {}, ThreadStarter start = {})
      : count_(count), make_(std::move(make)), start_(std::move(start)) {}
  LandmarkCache(const LandmarkCache&) = delete;
  LandmarkCache& operator=(const LandmarkCache&) = delete;
  ~LandmarkCache() {
    cancel_.store(true);
    if (worker_.joinable()) worker_.join();
  }

  // The count asked for.
  int count() const { return count_; }
  // The count it makes (or made) for the last map it was asked about: count() cut to what
  // fits in kMaxLandmarkBytes on that map (landmarksThatFit); count() before any.
  int countInUse() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return count_in_use_;
  }
  // Why the last attempt to make landmarks failed ("" if it did not).
  std::string lastError() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_error_;
  }

  // Landmarks whose bounds hold on `grid`, or null (then making them is under way, or none
  // fit on this map, or they could not be made: see lastError()).
  std::shared_ptr<const Landmarks> usableFor(const CostGrid& grid) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (ready_ && ready_->holdsFor(grid)) return ready_;
    count_in_use_ = landmarksThatFit(grid.cellCount(), count_);
    if (computing_ || count_in_use_ == 0) return nullptr;
    if (worker_.joinable()) worker_.join();  // finished: it cleared computing_
    // The floor is made on the worker thread too, from a copy of the grid and the landmarks
    // held: the plan that asked waits for neither.
    std::shared_ptr<const Landmarks> held = ready_;
    try {
      std::function<void()> body = [this, floor = grid, held, count = count_in_use_]() mutable {
        make(std::move(floor), held, count);
      };
      worker_ = start_ ? start_(std::move(body)) : std::thread(std::move(body));
      computing_ = true;
      last_error_.clear();
    } catch (const std::exception& e) {  // no thread (std::system_error), no memory for the copy
      last_error_ = std::string("could not start making landmarks: ") + e.what();
    }
    return nullptr;
  }

  // Waits until the landmarks under way (if any) are made.
  void wait() {
    std::thread worker;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      worker.swap(worker_);
    }
    if (worker.joinable()) worker.join();
  }

 private:
  // The worker thread's body: catches everything (an exception leaving a thread would end the
  // process); a failure leaves the landmarks held as they were.
  void make(CostGrid floor, const std::shared_ptr<const Landmarks>& held, int count) {
    yieldToPlans();
    std::shared_ptr<const Landmarks> made;
    std::string error;
    try {
      if (held && Landmarks::sameShape(held->grid(), floor)) cheapestOf(held->grid(), floor);
      made = make_ ? make_(floor, count, &cancel_) : Landmarks::compute(floor, count, &cancel_);
    } catch (const std::exception& e) {
      error = std::string("making landmarks failed: ") + e.what();
    } catch (...) {
      error = "making landmarks failed with an unknown exception";
    }
    std::lock_guard<std::mutex> done(mutex_);
    if (made) ready_ = std::move(made);
    last_error_ = error;
    computing_ = false;
  }

  // The landmarks are made beside the plans that need them now: on a machine with few cores
  // their thread would take a core from a plan and push it past its time limit, so it runs at
  // the lowest priority (Linux: a thread's own nice value; elsewhere as it is).
  static void yieldToPlans() {
#ifdef __linux__
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
  }

  // Each cell of `into` at most as costly as in `other` (an obstacle is the costliest).
  static void cheapestOf(const CostGrid& other, CostGrid& into) {
    for (std::size_t i = 0; i < into.cellCount(); ++i) {
      const std::uint8_t was = other.cellBytes()[i];
      if (was < into.cellBytes()[i]) into.setCost(into.cellAt(i), was);  // `was` is a cost, not an obstacle
    }
  }

  const int count_;
  const Maker make_;
  const ThreadStarter start_;
  mutable std::mutex mutex_;
  std::shared_ptr<const Landmarks> ready_;  // under mutex_
  bool computing_ = false;                  // under mutex_
  int count_in_use_ = count_;               // under mutex_
  std::string last_error_;                  // under mutex_
  std::thread worker_;
  std::atomic<bool> cancel_{false};
};

}  // namespace eaci
