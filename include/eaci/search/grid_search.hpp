// One search over the grid's moves, behind every exact search of the project: A*
// (shortestPath), the island leg fields (LegCostField) and reachability
// (reachableFrom). What differs between them is a
// parameter: a target to stop at (and steer towards), a window to stay in, whether to keep
// the moves for the route back, and whether distances matter at all.
//
// A route's cost is the sum of its moves' costs (CostGrid::moveCost); the "distance" a search
// finds is that cost, which on a binary map (every free cell of cost 0) is the grid distance.
//
// Two ways to run it: searchGrid returns a result of its own (a distance per window slot), and
// GridSearchWorkspace keeps its buffers for the next search (for callers that search often and
// read few cells, such as A*: only a 2-byte generation stamp per cell is cleared, on
// allocation and then once per 65 535 searches; it tells the labels of this search from older
// ones). Both run the same loop and find the same distances
// and moves: cells leave the open list in one total order (SearchEntry), whatever the queue.
// The workspace's search that meets in the middle (cheapestRouteBetween) has a queue of its
// own (BucketQueue: no heap, a cell may be labelled twice), with the same costs.
//
// The loop's speed comes from: an open list that keeps only its lowest priorities in a heap
// (SearchQueue) and drops entries gone stale before they reach it, integer priority compares,
// the allowed moves of a cell as one bit mask (no bounds checks away from the border), and, with
// a workspace, no clearing of whole-map arrays.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "eaci/parallel/stop_poll.hpp"
#include "eaci/parallel/worker_group.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/search/bucket_queue.hpp"
#include "eaci/search/landmarks.hpp"

namespace eaci {

// Octile distance: the length of the shortest 8-connected path on an empty grid, a
// consistent A* heuristic under both corner rules. No move costs less than its length (the
// cheapest cell, cost 0, weighs a move by exactly 1), so it stays consistent for route costs.
inline double octileDistance(Cell a, Cell b) {
  const int dr = std::abs(a.row - b.row), dc = std::abs(a.col - b.col);
  return (kSqrt2 - 1.0) * std::min(dr, dc) + std::max(dr, dc);
}

// A rectangle of cells, stored row-major ("slots"); the search never leaves it.
struct CellWindow {
  int row0 = 0, col0 = 0, rows = 0, cols = 0;

  static CellWindow whole(const CostGrid& grid) { return {0, 0, grid.height(), grid.width()}; }
  // The bounding box of `cells` grown by `margin`, clipped to the grid.
  static CellWindow around(const CostGrid& grid, const CellPath& cells, int margin) {
    int r0 = cells.front().row, r1 = r0, c0 = cells.front().col, c1 = c0;
    for (const Cell& c : cells) {
      r0 = std::min(r0, c.row);
      r1 = std::max(r1, c.row);
      c0 = std::min(c0, c.col);
      c1 = std::max(c1, c.col);
    }
    const int top = std::max(0, r0 - margin), left = std::max(0, c0 - margin);
    return {top, left, std::min(grid.height() - 1, r1 + margin) - top + 1,
            std::min(grid.width() - 1, c1 + margin) - left + 1};
  }

  bool contains(Cell c) const { return c.row >= row0 && c.col >= col0 && c.row < row0 + rows && c.col < col0 + cols; }
  std::size_t size() const { return static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols); }
  std::size_t slot(Cell c) const {
    return static_cast<std::size_t>(c.row - row0) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c.col - col0);
  }
  Cell cellAt(std::size_t s) const {
    return Cell{row0 + static_cast<int>(s / static_cast<std::size_t>(cols)),
                col0 + static_cast<int>(s % static_cast<std::size_t>(cols))};
  }
};

enum class SearchOrder {
  kByDistance,  // Dijkstra / A*: cells settle in order of route cost (exact costs)
  kAnyOrder,    // a flood: which cells are reachable, nothing more (distance 0 on each)
};

struct GridSearchRequest {
  Cell source;
  std::optional<Cell> target;  // stop once it is settled; A* steers towards it (octile heuristic)
  std::optional<CellWindow> window;  // default: the whole grid
  bool keep_moves = false;     // remember the move into each cell, for routeTo()
  SearchOrder order = SearchOrder::kByDistance;
  bool reverse_costs = false;  // costs of routes *to* the source (see searchGrid)
  // The caller's stop check, ticked once per cell taken off the open list (or flooded); once
  // it says stop the search ends there, with the labels it has (GridSearchResult::stopped).
  StopPoll* stop = nullptr;
};

struct GridSearchResult {
  CellWindow window;
  std::vector<double> distance;        // per window slot: route cost from the source; +infinity = not reached
  std::vector<std::uint8_t> came_dir;  // per window slot (keep_moves): the move into it, kNoMove at the source
  double largest_distance = 0.0;       // over the settled cells
  bool stopped = false;                // ended by the request's stop check: distances are partial
  static constexpr std::uint8_t kNoMove = 0xFF;

  double at(Cell c) const {
    return window.contains(c) ? distance[window.slot(c)] : std::numeric_limits<double>::infinity();
  }
  bool reached(Cell c) const { return std::isfinite(at(c)); }

  // The cells from the source to `c` (needs keep_moves); empty when `c` was not reached.
  CellPath routeTo(Cell c) const {
    CellPath route;
    if (!reached(c) || came_dir.empty()) return route;
    for (;;) {
      route.push_back(c);
      const std::uint8_t d = came_dir[window.slot(c)];
      if (d == kNoMove) break;
      c = Cell{c.row - kDirRow[d], c.col - kDirCol[d]};
    }
    std::reverse(route.begin(), route.end());
    return route;
  }
};

namespace detail {
struct SearchEntry {
  double priority;
  double cost;
  std::uint32_t slot;
  // Min-heap on priority; among equals prefer the larger cost (deeper node), then the lower slot.
  bool operator>(const SearchEntry& o) const {
    if (priority != o.priority) return priority > o.priority;
    if (cost != o.cost) return cost < o.cost;
    return slot > o.slot;
  }
};

// A 4-ary min-heap of entries in SearchEntry's order. Priorities are never negative, so their
// bit patterns order like their values: the heap compares them as integers (the common case,
// no tie, picks a child without a branch).
class SearchHeap {
 public:
  struct Item {
    std::uint64_t key;  // the priority's bits
    double cost;
    std::uint32_t slot;
  };
  static Item itemOf(const SearchEntry& e) {
    std::uint64_t bits;
    std::memcpy(&bits, &e.priority, sizeof bits);
    return Item{bits, e.cost, e.slot};
  }
  static SearchEntry entryOf(const Item& item) {
    double priority;
    std::memcpy(&priority, &item.key, sizeof priority);
    return SearchEntry{priority, item.cost, item.slot};
  }

  void clear() { heap_.clear(); }
  bool empty() const { return heap_.empty(); }
  const Item& front() const { return heap_.front(); }  // not empty
  void push(const Item& item) {
    std::size_t i = heap_.size();
    heap_.push_back(item);
    while (i > 0) {
      const std::size_t parent = (i - 1) / 4;
      if (!before(item, heap_[parent])) break;
      heap_[i] = heap_[parent];
      i = parent;
    }
    heap_[i] = item;
  }
  Item pop() {  // not empty
    const Item top = heap_.front();
    const Item last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) siftDown(0, last);
    return top;
  }
  // Adds items in any order; heapify() restores the heap.
  void append(const Item& item) { heap_.push_back(item); }
  void heapify() {
    for (std::size_t i = heap_.size() / 4 + 1; i-- > 0;)
      if (i < heap_.size()) siftDown(i, heap_[i]);
  }

 private:
  static bool before(const Item& a, const Item& b) {
    if (__builtin_expect(a.key != b.key, 1)) return a.key < b.key;
    if (a.cost != b.cost) return a.cost > b.cost;
    return a.slot < b.slot;
  }
  // Puts `item` at `i` or below, moving smaller children up.
  void siftDown(std::size_t i, const Item item) {
    const std::size_t n = heap_.size();
    for (;;) {
      const std::size_t first = 4 * i + 1;
      if (first >= n) break;
      std::size_t best = first;
      if (first + 4 <= n) {
        for (std::size_t k = first + 1; k < first + 4; ++k) best = before(heap_[k], heap_[best]) ? k : best;
      } else {
        for (std::size_t k = first + 1; k < n; ++k) best = before(heap_[k], heap_[best]) ? k : best;
      }
      if (!before(heap_[best], item)) break;
      heap_[i] = heap_[best];
      i = best;
    }
    heap_[i] = item;
  }

  std::vector<Item> heap_;
};

// The open list. Entries are sorted into buckets of priority width 1/4 (a ring of them, and a
// pile for priorities beyond the ring); only the lowest bucket's entries sit in the heap, so the
// heap stays small, and the entries of a bucket that went stale while they waited never enter it. Every entry in the heap comes before every entry outside it (a bucket's
// number never falls as the priority grows), so entries leave in SearchEntry's order, the
// same as from one big heap: no two entries compare equal (a cell is pushed again only with a
// smaller cost), so that order is total.
class SearchQueue {
 public:
  void clear() {
    heap_.clear();
    for (auto& bucket : ring_) bucket.clear();
    beyond_.clear();
    beyond_lowest_ = kNoBucket;
    current_ = 0;
    outside_heap_ = 0;
  }
  void push(const SearchEntry& entry) {
    const std::uint64_t bucket = bucketOf(entry.priority);
    if (bucket <= current_) {
      heap_.push(SearchHeap::itemOf(entry));
      return;
    }
    ++outside_heap_;
    if (bucket < current_ + kRing) {
      ring_[bucket % kRing].push_back(entry);
    } else {
      beyond_.push_back(entry);
      beyond_lowest_ = std::min(beyond_lowest_, bucket);
    }
  }
  // The next entry into `next`; false when there is none. Entries that `stale` finds out of
  // date (a cheaper label came since) may be dropped on the way: they would be skipped anyway.
  template <class Stale>
  bool pop(SearchEntry& next, const Stale& stale) {
    if (!peek(next, stale)) return false;
    heap_.pop();
    return true;
  }
  // The entry pop() would give next, left in the queue; false when there is none.
  template <class Stale>
  bool peek(SearchEntry& next, const Stale& stale) {
    while (heap_.empty()) {
      if (outside_heap_ == 0) return false;
      refill(stale);
    }
    next = SearchHeap::entryOf(heap_.front());
    return true;
  }

 private:
  static constexpr std::uint64_t kRing = 256;
  static constexpr std::size_t kKeptBucketCapacity = 256;
  static constexpr std::uint64_t kNoBucket = std::numeric_limits<std::uint64_t>::max();
  // Never falls as the priority grows (huge priorities share the last bucket).
  static std::uint64_t bucketOf(double priority) {
    return static_cast<std::uint64_t>(std::min(priority * 4.0, 4.0e18));
  }

  // Moves the lowest non-empty bucket, less its stale entries, into the (empty) heap.
  template <class Stale>
  void refill(const Stale& stale) {
    std::uint64_t next = current_ + 1;
    while (next < current_ + kRing && ring_[next % kRing].empty()) ++next;
    current_ = next < current_ + kRing ? std::min(next, beyond_lowest_) : beyond_lowest_;
    if (beyond_lowest_ < current_ + kRing) {  // the pile's entries that the ring now covers join it
      std::size_t kept = 0;
      beyond_lowest_ = kNoBucket;
      for (const SearchEntry& e : beyond_) {
        const std::uint64_t bucket = bucketOf(e.priority);
        if (bucket < current_ + kRing) {
          ring_[bucket % kRing].push_back(e);
        } else {
          beyond_[kept++] = e;
          beyond_lowest_ = std::min(beyond_lowest_, bucket);
        }
      }
      beyond_.resize(kept);
    }
    std::vector<SearchEntry>& bucket = ring_[current_ % kRing];
    outside_heap_ -= bucket.size();
    for (const SearchEntry& e : bucket)
      if (!stale(e)) heap_.append(SearchHeap::itemOf(e));
    heap_.heapify();
    // A bucket that grew large gives its memory back: the ring holds few entries at a time,
    // but each of its buckets would otherwise keep the most it ever held.
    if (bucket.capacity() > kKeptBucketCapacity) std::vector<SearchEntry>().swap(bucket);
    else bucket.clear();
  }

  SearchHeap heap_;
  std::vector<std::vector<SearchEntry>> ring_ = std::vector<std::vector<SearchEntry>>(kRing);
  std::vector<SearchEntry> beyond_;
  std::uint64_t beyond_lowest_ = kNoBucket;  // the pile's lowest bucket
  std::uint64_t current_ = 0;                // the heap's bucket
  std::size_t outside_heap_ = 0;             // entries in the ring and the pile
};

// The neighbours of a cell by direction, as window slot and grid index offsets, and the allowed
// moves from a cell (CostGrid::movesFrom) that stay in the window. Cells off the window's
// border (all eight neighbours inside it) skip the window checks.
class SearchNeighbourhood {
 public:
  SearchNeighbourhood(const CostGrid& grid, const CellWindow& window)
      : grid_(grid), window_(window),
        row_lo_(std::max(0, window.row0)), row_hi_(std::min(grid.height(), window.row0 + window.rows)),
        col_lo_(std::max(0, window.col0)), col_hi_(std::min(grid.width(), window.col0 + window.cols)) {
    for (int d = 0; d < kDirections; ++d) {
      slot_step_[d] = static_cast<std::ptrdiff_t>(kDirRow[d]) * window.cols + kDirCol[d];
      index_step_[d] = static_cast<std::ptrdiff_t>(kDirRow[d]) * grid.width() + kDirCol[d];
    }
  }

  std::uint32_t slotTowards(std::uint32_t slot, int dir) const {
    return static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(slot) + slot_step_[dir]);
  }
  std::size_t indexTowards(std::size_t index, int dir) const {
    return static_cast<std::size_t>(static_cast<std::ptrdiff_t>(index) + index_step_[dir]);
  }

  // Bit d: the move in direction d from `here` is allowed and ends in the window.
  unsigned movesFrom(Cell here) const {
    const unsigned moves = grid_.movesFrom(here);
    if (here.row > row_lo_ && here.row + 1 < row_hi_ && here.col > col_lo_ && here.col + 1 < col_hi_) return moves;
    unsigned in_window = 0;
    for (int d = 0; d < kDirections; ++d) in_window |= static_cast<unsigned>(window_.contains(step(here, d))) << d;
    return moves & in_window;
  }

 private:
  const CostGrid& grid_;
  const CellWindow& window_;
  int row_lo_, row_hi_, col_lo_, col_hi_;  // window and grid overlap: rows [row_lo_, row_hi_), columns likewise
  std::ptrdiff_t slot_step_[kDirections];
  std::ptrdiff_t index_step_[kDirections];
};

inline int lowestBit(unsigned bits) { return __builtin_ctz(bits); }

// Labels each cell one allowed move from the settled cell `here` (window slot `slot`, route
// cost `cost`) that the move reaches more cheaply than its label says, and hands it to
// on_label(slot, cell, cost). A move costs by the cell it enters; with `reverse_costs` by the
// cell it leaves (the real move goes the other way: costs of routes *to* the source).
template <class Labels, class OnLabel>
void relaxMoves(const CostGrid& grid, const SearchNeighbourhood& around, std::uint32_t slot, Cell here, double cost,
                bool reverse_costs, Labels& labels, const OnLabel& on_label) {
  const std::size_t index = grid.index(here);
  for (unsigned moves = around.movesFrom(here); moves != 0; moves &= moves - 1) {
    const int d = lowestBit(moves);
    const std::uint32_t j = around.slotTowards(slot, d);
    const double g = cost + grid.moveCostInto(reverse_costs ? index : around.indexTowards(index, d), d);
    if (g >= labels.distance(j)) continue;
    labels.label(j, g, static_cast<std::uint8_t>(d));
    on_label(j, step(here, d), g);
  }
}

// The loop of every search, on labels kept by `Labels`: distance(slot) (+infinity when not
// reached) and label(slot, distance, move). Returns the largest settled distance; `stopped`
// says whether the request's stop check ended it.
template <class Labels>
double runGridSearch(const CostGrid& grid, const GridSearchRequest& request, const CellWindow& window, Labels& labels,
                     SearchQueue& open, std::vector<std::uint32_t>& frontier, bool& stopped) {
  stopped = false;
  if (!grid.isFree(request.source) || !window.contains(request.source)) return 0.0;
  StopPoll never;
  StopPoll& poll = request.stop != nullptr ? *request.stop : never;
  const SearchNeighbourhood around(grid, window);
  const auto source = static_cast<std::uint32_t>(window.slot(request.source));
  labels.label(source, 0.0, GridSearchResult::kNoMove);

  if (request.order == SearchOrder::kAnyOrder) {  // a flood: depth first, each cell once
    frontier.clear();
    frontier.push_back(source);
    while (!frontier.empty()) {
      if (poll.tick()) {
        stopped = true;
        return 0.0;
      }
      const std::uint32_t slot = frontier.back();
      frontier.pop_back();
      const Cell here = window.cellAt(slot);
      for (unsigned moves = around.movesFrom(here); moves != 0; moves &= moves - 1) {
        const std::uint32_t j = around.slotTowards(slot, lowestBit(moves));
        if (labels.distance(j) == 0.0) continue;
        labels.label(j, 0.0, GridSearchResult::kNoMove);
        frontier.push_back(j);
      }
    }
    return 0.0;
  }

  const bool steer = request.target.has_value();
  const Cell target = request.target.value_or(Cell{});
  constexpr std::uint32_t kNoTarget = std::numeric_limits<std::uint32_t>::max();
  const std::uint32_t target_slot =
      steer && window.contains(target) ? static_cast<std::uint32_t>(window.slot(target)) : kNoTarget;
  double largest_distance = 0.0;
  open.clear();
  open.push({steer ? octileDistance(request.source, target) : 0.0, 0.0, source});
  const auto stale = [&labels](const SearchEntry& e) { return e.cost > labels.distance(e.slot); };
  SearchEntry top;
  while (open.pop(top, stale)) {
    if (poll.tick()) {  // counts stale entries too: they cost a pop
      stopped = true;
      break;
    }
    if (stale(top)) continue;  // settled before, by a shorter way
    largest_distance = std::max(largest_distance, top.cost);
    if (top.slot == target_slot) break;
    relaxMoves(grid, around, top.slot, window.cellAt(top.slot), top.cost, request.reverse_costs, labels,
               [&](std::uint32_t j, Cell next, double g) { open.push({steer ? g + octileDistance(next, target) : g, g, j}); });
  }
  return largest_distance;
}

// Lower bounds of the cost from the source to a cell and from the cell to the target, for the
// search that meets in the middle: the octile distance, raised by landmark bounds where
// landmarks are at hand. Both are consistent (a move changes them by no more than it costs).
struct MeetingBounds {
  Cell source, target;
  const Landmarks* landmarks = nullptr;
  const float* source_marks = nullptr;  // landmark distances of the source and the target
  const float* target_marks = nullptr;
  double span = 0.0;  // a lower bound of the whole route's cost (the same from either end)

  // `marks`: null, or landmarks that bound nothing (count 0), for the octile bound alone.
  MeetingBounds(Cell s, Cell t, std::size_t s_index, std::size_t t_index, const Landmarks* marks)
      : source(s), target(t), landmarks(marks != nullptr && marks->count() > 0 ? marks : nullptr) {
    span = octileDistance(s, t);
    if (landmarks == nullptr) return;
    source_marks = landmarks->of(s_index);
    target_marks = landmarks->of(t_index);
    span = std::max(span, landmarks->lowerBound(source_marks, target_marks));
  }

  // Half of (bound to the target - bound from the source) at cell `c` of grid index `index`:
  // the potential the forward side adds and the backward side subtracts.
  double halfDifference(Cell c, std::size_t index) const {
    double from_source = octileDistance(c, source), to_target = octileDistance(c, target);
    if (landmarks != nullptr) {
      double marks_source, marks_target;
      landmarks->lowerBounds(landmarks->of(index), source_marks, target_marks, marks_source, marks_target);
      from_source = std::max(from_source, marks_source);
      to_target = std::max(to_target, marks_target);
    }
    return 0.5 * (to_target - from_source);
  }
};

// One side of a search that meets in the middle (GridSearchWorkspace::cheapestRouteBetween):
// the search from the source (`forward`) or from the target over the reversed moves. Its cells
// leave the open list in order of route cost plus a potential, half the difference of the
// bounds to the far end and from the near end (MeetingBounds), which keeps every move's
// reduced cost >= 0 on both sides alike, so each side is a Dijkstra search on the same reduced
// costs, with a bucket queue (BucketQueue: a cell may be labelled again within a bucket).
template <class Labels>
struct MeetingSide {
  Labels labels;
  BucketQueue* open;
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
  bool stale(const BucketEntry& e) const { return e.cost > labels.distance(e.slot); }
  void push(std::uint32_t slot, Cell c, double g) { open->push(priority(c, slot, g), BucketEntry{g, slot}); }

  // Takes up to `cells` cells off the open list; labels only its own slots, reads nothing of
  // the other side. Adds the cells it took to `taken`. Ends early once `stop` says so.
  void round(const CostGrid& grid, const CellWindow& window, const SearchNeighbourhood& around, int cells) {
    touched->clear();
    const auto is_stale = [this](const BucketEntry& e) { return stale(e); };
    BucketEntry top;
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

// Labels in the result's own arrays (filled with +infinity first).
struct ResultLabels {
  double* distances;
  std::uint8_t* moves;  // null: moves not kept
  double distance(std::uint32_t slot) const { return distances[slot]; }
  void label(std::uint32_t slot, double d, std::uint8_t move) {
    distances[slot] = d;
    if (moves != nullptr) moves[slot] = move;
  }
};
}  // namespace detail

// The search itself. A blocked or off-window source reaches nothing. A move costs by the cell
// it enters, so costs from the source are not costs to it on a cost map (they are on a binary
// map): a field that must hold costs *to* its source searches the reversed moves
// (`reverse_costs`), which charge the cell a move leaves instead.
// The open list and flood stack of searchGrid, kept by a caller that runs many small searches
// (one per island leg), so that each costs no allocation of its own.
struct GridSearchScratch {
  detail::SearchQueue open;
  std::vector<std::uint32_t> frontier;
};

inline GridSearchResult searchGrid(const CostGrid& grid, const GridSearchRequest& request, GridSearchScratch& scratch) {
  GridSearchResult result;
  result.window = request.window.value_or(CellWindow::whole(grid));
  result.distance.assign(result.window.size(), std::numeric_limits<double>::infinity());
  if (request.keep_moves) result.came_dir.assign(result.window.size(), GridSearchResult::kNoMove);
  detail::ResultLabels labels{result.distance.data(), request.keep_moves ? result.came_dir.data() : nullptr};
  result.largest_distance =
      detail::runGridSearch(grid, request, result.window, labels, scratch.open, scratch.frontier, result.stopped);
  return result;
}

inline GridSearchResult searchGrid(const CostGrid& grid, const GridSearchRequest& request) {
  GridSearchScratch scratch;
  return searchGrid(grid, request, scratch);
}

// The same search, into buffers that stay for the next one: a caller that keeps a workspace
// allocates once per map size, and a search costs only the cells it labels (each label carries
// the number of the search that wrote it, so the buffers need no clearing between searches).
// The moves are always kept (keep_moves is implied). Read the answers before the next search.
class GridSearchWorkspace {
 public:
  void search(const CostGrid& grid, const GridSearchRequest& request) {
    window_ = request.window.value_or(CellWindow::whole(grid));
    prepare(window_.size());
    Labels labels = currentLabels();
    largest_distance_ = detail::runGridSearch(grid, request, window_, labels, open_, frontier_, stopped_);
  }

  // A cheapest route from `source` to `target` (both free) by two searches that meet in the
  // middle (detail::MeetingSide), the same cost as A*'s route (of several equally cheap routes
  // it may return another). The two sides take turns in rounds of 16, 32, ... up to
  // kMeetingRound cells, each on its own labels; between rounds the cells either side labelled
  // are checked against the other's labels (every pair offers a route, the cheapest so far is
  // mu), and the search ends
  // once the two sides' lowest open priorities (BucketQueue::lowerBound) add up to
  // mu + octile(source, target): no cheaper
  // route is left. With `threads` >= 2 the two sides of each full-size round run at the
  // same time where a second thread, kept with the workspace, claims one (WorkerGroup::share);
  // the rounds, and so the route, are the same on one thread.
  // Empty when the target cannot be reached. at() and routeTo() do not answer for it.
  // `stop`: the caller's stop check; each side ticks a poll of its own (StopPoll::
  // forAnotherThread) once per cell it takes, and once either says stop the search ends
  // with no route (stopped() true, `stop` latched).
  CellPath cheapestRouteBetween(const CostGrid& grid, Cell source, Cell target, int threads = 1,
                                double* cost = nullptr, StopPoll* stop = nullptr) {
    window_ = CellWindow::whole(grid);
    prepare(window_.size());
    if (backward_.capacity < window_.size()) backward_.allocate(window_.size());
    CellPath route;
    if (cost != nullptr) *cost = std::numeric_limits<double>::infinity();
    expanded_ = 0;
    stopped_ = false;
    if (!grid.isFree(source) || !grid.isFree(target)) return route;
    const std::shared_ptr<const Landmarks> landmarks = landmarks_ ? landmarks_->usableFor(grid) : nullptr;
    const detail::MeetingBounds bounds(source, target, grid.index(source), grid.index(target), landmarks.get());
    const double span = bounds.span;
    const StopPoll side_stop = stop != nullptr ? stop->forAnotherThread() : StopPoll{};
    detail::MeetingSide<Labels> sides[2] = {
        {currentLabels(), &meeting_open_, &touched_[0].cells, &bounds, true, side_stop},
        {backward_.of(generation_), &backward_open_, &touched_[1].cells, &bounds, false, side_stop}};
    for (int side = 0; side < 2; ++side) {
      const Cell end = side == 0 ? source : target;
      const auto slot = static_cast<std::uint32_t>(window_.slot(end));
      sides[side].labels.label(slot, 0.0, GridSearchResult::kNoMove);
      sides[side].open->clear();
      sides[side].push(slot, end, 0.0);
    }
    const detail::SearchNeighbourhood around(grid, window_);
    double mu = source == target ? 0.0 : std::numeric_limits<double>::infinity();
    std::uint32_t meeting = static_cast<std::uint32_t>(window_.slot(source));
    int rounds = 0;
    for (;;) {
      double lowest[2];
      const bool open_forward = sides[0].open->lowerBound(lowest[0], [&](const detail::BucketEntry& e) { return sides[0].stale(e); });
      const bool open_backward = sides[1].open->lowerBound(lowest[1], [&](const detail::BucketEntry& e) { return sides[1].stale(e); });
      if (!open_forward || !open_backward) break;  // one side has settled all it can reach
      if (lowest[0] + lowest[1] >= mu + span) break;
      // Rounds grow from kFirstMeetingRound cells to kMeetingRound, so that a short route costs
      // few cells more than the search needs; the small ones stay on this thread.
      const int round_cells = std::min(kMeetingRound, kFirstMeetingRound << std::min(rounds++, 20));
      const auto run_side = [&](int side) { sides[side].round(grid, window_, around, round_cells); };
      if (threads >= 2 && round_cells == kMeetingRound) {
        // Each side goes to the first thread that claims it: a worker that wakes late leaves
        // both to this thread rather than holding the round up.
        if (!meeting_workers_) meeting_workers_ = std::make_unique<WorkerGroup>(2);
        std::atomic<int> next_side{0};
        meeting_workers_->share([&](int) {
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
          const double through = sides[0].labels.distance(j) + sides[1].labels.distance(j);
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
    if (cost != nullptr) *cost = mu;
    if (!std::isfinite(mu)) return route;
    route = routeTo(window_.cellAt(meeting));  // from the source to the meeting cell
    for (Cell c = window_.cellAt(meeting);;) {  // on from the meeting cell to the target
      const std::uint8_t d = backward_.moves[window_.slot(c)];
      if (d == GridSearchResult::kNoMove) break;
      c = Cell{c.row - kDirRow[d], c.col - kDirCol[d]};
      route.push_back(c);
    }
    return route;
  }

  // Keep `count` landmarks (Landmarks, LandmarkCache) for cheapestRouteBetween: made in the
  // background on the first costmap it searches, used by later searches on that costmap (or a
  // costlier one). 0 (the default): none, octile bounds alone. For callers that plan many times
  // on one costmap; a change of count drops the landmarks kept.
  void useLandmarks(int count) {
    if (count == (landmarks_ ? landmarks_->count() : 0)) return;
    landmarks_.reset();
    if (count > 0) landmarks_ = std::make_unique<LandmarkCache>(count);
  }
  // The landmark cache (null without useLandmarks), e.g. to wait for landmarks under way.
  LandmarkCache* landmarkCache() { return landmarks_.get(); }

  // The cells the last cheapestRouteBetween took off its two open lists (its work, for benchmarks).
  std::size_t expandedCells() const { return expanded_; }
  // The last search (or cheapestRouteBetween) was ended by its stop check: its labels are
  // partial, and cheapestRouteBetween returned no route.
  bool stopped() const { return stopped_; }

  const CellWindow& window() const { return window_; }
  double largestDistance() const { return largest_distance_; }  // over the settled cells
  // Route cost from the source; +infinity = not reached (or outside the window).
  double at(Cell c) const {
    if (!window_.contains(c)) return std::numeric_limits<double>::infinity();
    return currentLabels().distance(static_cast<std::uint32_t>(window_.slot(c)));
  }
  bool reached(Cell c) const { return std::isfinite(at(c)); }
  // The cells from the source to `c` of a search by distance; empty when `c` was not reached.
  CellPath routeTo(Cell c) const {
    CellPath route;
    if (!reached(c)) return route;
    for (;;) {
      route.push_back(c);
      const std::uint8_t d = forward_.moves[window_.slot(c)];
      if (d == GridSearchResult::kNoMove) break;
      c = Cell{c.row - kDirRow[d], c.col - kDirCol[d]};
    }
    std::reverse(route.begin(), route.end());
    return route;
  }

 private:
  // A slot's distance and move belong to this search when its generation is this search's;
  // generation 0 is no search's.
  struct Labels {
    double* distances;
    std::uint8_t* moves;
    std::uint16_t* generations;
    std::uint16_t generation;
    double distance(std::uint32_t slot) const {
      return generations[slot] == generation ? distances[slot] : std::numeric_limits<double>::infinity();
    }
    void label(std::uint32_t slot, double d, std::uint8_t move) {
      distances[slot] = d;
      moves[slot] = move;
      generations[slot] = generation;
    }
  };
  // One set of label arrays, kept from search to search.
  struct LabelArrays {
    std::unique_ptr<double[]> distances;
    std::unique_ptr<std::uint8_t[]> moves;
    std::unique_ptr<std::uint16_t[]> generations;
    std::size_t capacity = 0;

    void allocate(std::size_t slots) {  // every label of generation 0: no search's
      generations.reset();  // the old buffers go first
      distances.reset();
      moves.reset();
      generations.reset(new std::uint16_t[slots]());
      distances.reset(new double[slots]);
      moves.reset(new std::uint8_t[slots]);
      capacity = slots;
    }
    void forgetAll() { std::fill(generations.get(), generations.get() + capacity, std::uint16_t{0}); }
    Labels of(std::uint16_t generation) const {
      return Labels{distances.get(), moves.get(), generations.get(), generation};
    }
  };
  Labels currentLabels() const { return forward_.of(generation_); }

  // Room for `slots` labels, none of them this search's. Only the generations are ever cleared
  // (2 bytes a slot, once per 65 535 searches); distances and moves are read only where the
  // generation says they were written.
  void prepare(std::size_t slots) {
    if (slots > forward_.capacity) {
      backward_ = LabelArrays{};  // numbered afresh below: the backward labels go too
      forward_.allocate(slots);
      generation_ = 0;
    }
    if (++generation_ == 0) {  // the numbers wrapped round: forget every label
      forward_.forgetAll();
      backward_.forgetAll();
      generation_ = 1;
    }
  }

  LabelArrays forward_;
  std::uint16_t generation_ = 0;
  // cheapestRouteBetween: the labels of the side that starts at the target, both sides' queues
  // and round lists, and the thread of the second side.
  static constexpr int kFirstMeetingRound = 16;
  static constexpr int kMeetingRound = 2048;
  LabelArrays backward_;
  // What the two sides write during a round sits on cache lines of its own.
  alignas(64) detail::BucketQueue meeting_open_;
  alignas(64) detail::BucketQueue backward_open_;
  struct alignas(64) RoundCells {
    std::vector<std::uint32_t> cells;
  };
  RoundCells touched_[2];
  std::unique_ptr<WorkerGroup> meeting_workers_;
  std::unique_ptr<LandmarkCache> landmarks_;  // useLandmarks
  std::size_t expanded_ = 0;                   // expandedCells
  bool stopped_ = false;                       // stopped()
  CellWindow window_;
  double largest_distance_ = 0.0;
  alignas(64) detail::SearchQueue open_;
  std::vector<std::uint32_t> frontier_;
};

}  // namespace eaci
