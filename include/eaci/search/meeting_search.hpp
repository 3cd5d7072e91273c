// A cheapest route by two searches that meet in the middle, one from each end, on one or two
// threads, with landmark bounds where a LandmarkCache has them: the exact search of a planner
// that plans many times on large maps (geodesic islands' route on maps of 256 x 256 cells and
// more). Its labels keep costs as floats (7 bytes a cell and side, where A*'s keep 11), so a
// label is a route's cost rounded at every move: the route costs what A*'s costs (searchGrid)
// to within that rounding, n moves x 2^-24 of the cost each way (a few millionths on a route of
// a hundred moves), and its cost is summed again exactly along it. Of several equally cheap
// routes it may pick another.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "eaci/grid/cell_window.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/parallel/worker_group.hpp"
#include "eaci/search/bucket_queue.hpp"
#include "eaci/search/landmark_cache.hpp"
#include "eaci/search/landmarks.hpp"
#include "eaci/search/neighbourhood.hpp"
#include "eaci/search/octile.hpp"
#include "eaci/search/route_back.hpp"
#include "eaci/search/search_labels.hpp"

namespace eaci {
namespace detail {

// Lower bounds of the cost from the source to a cell and from the cell to the target, for the
// search that meets in the middle: the octile distance, raised by landmark bounds where
// landmarks are at hand. Both are consistent (a move changes them by no more than it costs).
struct MeetingBounds {
  Cell source, target;
  const Landmarks* landmarks = nullptr;
  const float* source_marks = nullptr;  // landmark costs of the source and the target
  const float* target_marks = nullptr;
  double span = 0.0;  // a lower bound of the whole route's cost (the same from either end)

  // `marks`: null, or landmarks that bound nothing (count 0), for the octile bound alone.
  MeetingBounds(Cell s, Cell t, std::size_t s_index, std::size_t t_index, const Landmarks* marks)
      : source(s), target(t), landmarks(marks != nullptr && marks->count() > 0 ? marks : nullptr) {
    span = octileDistance(s, t);
    if (landmarks == nullptr) return;
    source_marks = landmarks->of(s_index);
    target_marks = landmarks->of(t_index);
    if (!landmarks->reaches(source_marks)) {  // another part of the map than the landmarks': octile alone
      landmarks = nullptr;
      return;
    }
    span = std::max(span, landmarks->lowerBound(source_marks, target_marks));
  }

  // Half of (bound to the target - bound from the source) at cell `c` of grid index `index`:
  // the potential the forward side adds and the backward side subtracts. Each bound is the
  // larger of the octile distance and the landmarks' (both consistent, so is their maximum):
  // on rooms the landmarks' is the stronger almost everywhere, on SLAM maps' open halls and
  // speckle often the octile distance (the landmarks' bounds alone there took a plan 1.2-1.4 x
  // as long: docs/benchmarks.md, section 12).
  double halfDifference(Cell c, std::size_t index) const {
    const double octile_source = octileDistance(c, source), octile_target = octileDistance(c, target);
    if (landmarks != nullptr) {
      double marks_source, marks_target;
      landmarks->lowerBounds(landmarks->of(index), source_marks, target_marks, marks_source, marks_target);
      return 0.5 * (std::max(marks_target, octile_target) - std::max(marks_source, octile_source));
    }
    return 0.5 * (octile_target - octile_source);
  }
};

// One side of the search (MeetingSearch::cheapestRoute): the search from the source
// (`forward`) or from the target over the reversed moves. Its cells leave the open list in
// order of route cost plus a potential, half the difference of the bounds to the far end and
// from the near end (MeetingBounds), which keeps every move's reduced cost >= 0 on both sides
// alike, so each side is a Dijkstra search on the same reduced costs, with a bucket queue
// (BucketQueue: a cell may be labelled again within a bucket).
struct MeetingSide {
  StampedLabels<float> labels;
  BucketQueue<FloatBucketEntry>* open;
  std::vector<std::uint32_t>* touched;  // the slots this side labelled in its last round
  const MeetingBounds* bounds;
  bool forward;
  StopPoll stop;          // this side's own (the sides may run on two threads)
  std::size_t taken = 0;  // cells taken off the open list (a cell labelled again counts again)

  // The window is the whole grid: a slot is the grid index. span / 2 keeps it >= 0.
  double priority(Cell c, std::uint32_t slot, double g) const {
    const double half = bounds->halfDifference(c, slot);
    return g + (forward ? half : -half) + 0.5 * bounds->span;
  }
  bool stale(const FloatBucketEntry& e) const { return e.cost > labels.cost(e.slot); }
  // `g` as the labels keep it (a float: the entry holds it exactly).
  void push(std::uint32_t slot, Cell c, double g) {
    open->push(priority(c, slot, g), FloatBucketEntry{static_cast<float>(g), slot});
  }

  // Takes up to `cells` cells off the open list; labels only its own slots, reads nothing of
  // the other side. Adds the cells it took to `taken`. Ends early once `stop` says so.
  void round(const CostGrid& grid, const CellWindow& window, const SearchNeighbourhood& around, int cells) {
    touched->clear();
    const auto is_stale = [this](const FloatBucketEntry& e) { return stale(e); };
    FloatBucketEntry top;
    for (int n = 0; n < cells && open->pop(top, is_stale); ++n, ++taken) {
      if (stop.tick()) return;
      relaxMoves(grid, around, top.slot, window.cellAt(top.slot), top.cost, !forward, labels,
                 [this](std::uint32_t j, Cell next, double g) {
                   touched->push_back(j);
                   push(j, next, g);
                 });
    }
  }
};
}  // namespace detail

// Keeps its buffers, its second thread and its landmarks from search to search.
class MeetingSearch {
 public:
  // A cheapest route from `source` to `target` (both free). The two sides take turns in rounds
  // of 16, 32, ... up to 256 cells, and of kMeetingRound cells once they have taken
  // kSmallRoundCells, each on its own labels; between rounds the cells
  // either side labelled are checked against the other's labels (every pair offers a route, the
  // cheapest so far is mu), and the search ends once the two sides' lowest open priorities
  // (BucketQueue::lowerBound) add up to mu + the bound of the whole route: no cheaper route is
  // left. With `threads` >= 2 the two sides of each full-size round run at the same time where
  // a second thread, kept with the search, claims one (WorkerGroup::share); the rounds, and so
  // the route, are the same on one thread.
  // Empty when the target cannot be reached. `cost`: the route's cost (routeCost, exact;
  // +infinity without one).
  // `stop`: the caller's stop check; each side ticks a poll of its own (StopPoll::
  // forAnotherThread) once per cell it takes, and once either says stop the search ends
  // with no route (stopped() true, `stop` latched).
  CellPath cheapestRoute(const CostGrid& grid, Cell source, Cell target, int threads = 1, double* cost = nullptr,
                         StopPoll* stop = nullptr) {
    const CellWindow window = CellWindow::whole(grid);
    labels_.prepare(window.size());
    CellPath route;
    if (cost != nullptr) *cost = std::numeric_limits<double>::infinity();
    expanded_ = 0;
    stopped_ = false;
    used_landmarks_ = false;
    if (!grid.isFree(source) || !grid.isFree(target)) return route;
    const std::shared_ptr<const Landmarks> landmarks = landmarks_ ? landmarks_->usableFor(grid) : nullptr;
    const detail::MeetingBounds bounds(source, target, grid.index(source), grid.index(target), landmarks.get());
    used_landmarks_ = bounds.landmarks != nullptr;
    const double span = bounds.span;
    const StopPoll side_stop = stop != nullptr ? stop->forAnotherThread() : StopPoll{};
    detail::MeetingSide sides[2] = {{labels_.of(0), &forward_open_, &touched_[0].cells, &bounds, true, side_stop},
                                    {labels_.of(1), &backward_open_, &touched_[1].cells, &bounds, false, side_stop}};
    for (int side = 0; side < 2; ++side) {
      const Cell end = side == 0 ? source : target;
      const auto slot = static_cast<std::uint32_t>(window.slot(end));
      sides[side].labels.label(slot, 0.0, kNoMove);
      sides[side].open->clear();
      sides[side].push(slot, end, 0.0);
    }
    const detail::SearchNeighbourhood around(grid, window);
    double mu = source == target ? 0.0 : std::numeric_limits<double>::infinity();
    std::uint32_t meeting = static_cast<std::uint32_t>(window.slot(source));
    int rounds = 0;
    for (;;) {
      double lowest[2];
      const bool open_forward = sides[0].open->lowerBound(lowest[0], [&](const detail::FloatBucketEntry& e) { return sides[0].stale(e); });
      const bool open_backward = sides[1].open->lowerBound(lowest[1], [&](const detail::FloatBucketEntry& e) { return sides[1].stale(e); });
      if (!open_forward || !open_backward) break;  // one side has settled all it can reach
      if (lowest[0] + lowest[1] >= mu + span) break;
      // Rounds grow from kFirstMeetingRound cells to kSmallMeetingRound and stay there until
      // the sides have taken kSmallRoundCells between them, then kMeetingRound: the search
      // ends only between rounds, so small rounds keep a short route's search from taking
      // many cells more than it needs (a fifth fewer on rooms of 0.16-0.25 M cells), and the
      // large ones, which a second thread may share, come only on routes long enough to pay
      // for the hand-over. The schedule depends on nothing but the rounds, so the route is
      // the same on any number of threads.
      const bool small = sides[0].taken + sides[1].taken < kSmallRoundCells;
      const int round_cells =
          std::min(small ? kSmallMeetingRound : kMeetingRound, kFirstMeetingRound << std::min(rounds++, 20));
      const auto run_side = [&](int side) { sides[side].round(grid, window, around, round_cells); };
      if (threads >= 2 && round_cells == kMeetingRound) {
        // Each side goes to the first thread that claims it: a worker that wakes late leaves
        // both to this thread rather than holding the round up.
        if (!workers_) workers_ = std::make_unique<WorkerGroup>(2);
        std::atomic<int> next_side{0};
        workers_->share([&](int) {
          for (int side = next_side.fetch_add(1, std::memory_order_relaxed); side < 2;
               side = next_side.fetch_add(1, std::memory_order_relaxed))
            run_side(side);
        });
      } else {
        run_side(0);
        run_side(1);
      }
      if (sides[0].stop.stopped() || sides[1].stop.stopped()) {
        stopped_ = true;
        break;
      }
      for (int side = 0; side < 2; ++side)
        for (std::uint32_t j : touched_[side].cells) {
          const double through = sides[0].labels.cost(j) + sides[1].labels.cost(j);
          if (through < mu) {
            mu = through;
            meeting = j;
          }
        }
    }
    expanded_ = sides[0].taken + sides[1].taken;
    if (stopped_) {
      if (stop != nullptr) stop->latch();
      return route;
    }
    if (!std::isfinite(mu)) return route;
    // From the meeting cell back to the source, reversed; then on to the target.
    const Cell meeting_cell = window.cellAt(meeting);
    appendRouteBack(window, meeting_cell, [&](std::size_t slot) { return sides[0].labels.moveInto(slot); }, route);
    std::reverse(route.begin(), route.end());
    route.pop_back();  // the meeting cell again first on the way to the target
    appendRouteBack(window, meeting_cell, [&](std::size_t slot) { return sides[1].labels.moveInto(slot); }, route);
    if (cost != nullptr) *cost = routeCost(grid, route);  // summed exactly, as A* sums it
    return route;
  }

  // Keep `count` landmarks (Landmarks, LandmarkCache): made in the background on the first
  // costmap it searches, used by later searches on that costmap (or a costlier one). 0 (the
  // default): none, octile bounds alone. For callers that plan many times on one costmap; a
  // change of count drops the landmarks kept: the cache's job in flight is cancelled and let
  // go, not waited for (LandmarkCache). `make`, `start`, `max_settle_asks`: how a new cache
  // makes them, starts its thread and settles a map size (LandmarkCache's; empty:
  // Landmarks::compute, std::thread, LandmarkCache::kMaxSettleAsks).
  void useLandmarks(int count, LandmarkCache::Maker make = {}, ThreadStarter start = {},
                    int max_settle_asks = LandmarkCache::kMaxSettleAsks) {
    if (count == (landmarks_ ? landmarks_->count() : 0)) return;
    landmarks_.reset();
    if (count > 0)
      landmarks_ = std::make_unique<LandmarkCache>(count, std::move(make), std::move(start), max_settle_asks);
  }
  // The landmark cache (null without useLandmarks): how many landmarks fit, why making them
  // failed, the landmarks that hold on a grid (LandmarkCache::usableFor).
  LandmarkCache* landmarkCache() { return landmarks_.get(); }

  // The cells the last search took off its two open lists (its work, for benchmarks).
  std::size_t expandedCells() const { return expanded_; }
  // The last search was ended by its stop check and returned no route.
  bool stopped() const { return stopped_; }
  // The last search had landmark bounds (for benchmarks).
  bool usedLandmarks() const { return used_landmarks_; }

 private:
  static constexpr int kFirstMeetingRound = 16;
  static constexpr int kSmallMeetingRound = 256;
  static constexpr std::size_t kSmallRoundCells = 32768;
  static constexpr int kMeetingRound = 2048;
  detail::KeptLabels<2, float> labels_;  // the forward side's, the backward side's (MeetingSearch: float)
  // What the two sides write during a round sits on cache lines of its own.
  alignas(64) detail::BucketQueue<detail::FloatBucketEntry> forward_open_;
  alignas(64) detail::BucketQueue<detail::FloatBucketEntry> backward_open_;
  struct alignas(64) RoundCells {
    std::vector<std::uint32_t> cells;
  };
  RoundCells touched_[2];
  std::unique_ptr<WorkerGroup> workers_;
  std::unique_ptr<LandmarkCache> landmarks_;  // useLandmarks
  std::size_t expanded_ = 0;                   // expandedCells
  bool stopped_ = false;                       // stopped()
  bool used_landmarks_ = false;                // usedLandmarks()
};

}  // namespace eaci
