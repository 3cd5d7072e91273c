// The open lists of every search: entries sorted into buckets of priority width 1/4 (a ring of
// 256 buckets, and a pile for priorities beyond the ring), in one of two disciplines.
//
// OrderedBucketQueue (A*, Dijkstra fields, the landmark-free searches of searchGrid and
// GridSearchWorkspace): only the lowest bucket's entries sit in a heap, so the heap stays small
// and the entries of a bucket that went stale while they waited never enter it. Every entry in
// the heap comes before every entry outside it (a bucket's number never falls as the priority
// grows), so entries leave in SearchEntry's order, the same as from one big heap: no two
// entries compare equal (a cell is pushed again only with a smaller cost), so that order is total.
//
// BucketQueue (the search that meets in the middle, landmarks): no heap; within a bucket
// entries leave first in, first out, so a cell may leave before a cheaper label for it arrives
// from a cell of the same bucket; the search then labels it again and it leaves again (a
// label-correcting search, as in Delta-stepping: Meyer & Sanders, J. Algorithms 49, 2003).
// The labels a search ends with are still exact: a cell whose cost is below the lowest bucket
// still open keeps its label (the cheapest route to it ran through cells that all left the
// list with their final labels). Bucket edges are the lower bounds the search stops on. It
// saves the heap (a sift per entry) and the order within a bucket, at the price of a few cells
// labelled twice. The order is fixed by the pushes alone, so a search gives the same labels on
// every run.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace eaci {
namespace detail {

// The buckets both queues file their entries in, and the walk from one non-empty bucket to the next.
template <class Entry>
class BucketRing {
 public:
  static constexpr double kWidth = 1.0 / 4.0;  // a bucket's priority width
  // Never falls as the priority grows (huge priorities share the last bucket).
  static std::uint64_t bucketOf(double priority) {
    return static_cast<std::uint64_t>(std::min(std::max(priority, 0.0) / kWidth, 4.0e18));
  }

  void clear() {
    for (auto& bucket : ring_) bucket.clear();
    pile_.clear();
    pile_lowest_ = kNoBucket;
    current_ = 0;
  }
  std::uint64_t current() const { return current_; }
  std::vector<Entry>& currentBucket() { return ring_[current_ % kRing]; }

  // Files `entry` in `bucket` (at least the current one).
  void file(std::uint64_t bucket, const Entry& entry) {
    if (bucket < current_ + kRing) {
      ring_[bucket % kRing].push_back(entry);
    } else {
      pile_.push_back({entry, bucket});
      pile_lowest_ = std::min(pile_lowest_, bucket);
    }
  }
  // Empties the current bucket; a bucket that grew large gives its memory back (the ring holds
  // few entries at a time, but each of its buckets would otherwise keep the most it ever held).
  void releaseCurrent() {
    std::vector<Entry>& bucket = currentBucket();
    if (bucket.capacity() > kKeptBucketCapacity) std::vector<Entry>().swap(bucket);
    else bucket.clear();
  }
  // Makes the next non-empty bucket after the current one current (some entry must be filed
  // beyond it); the pile's entries that the ring then covers join it.
  void advance() {
    std::uint64_t next = current_ + 1;
    while (next < current_ + kRing && next < pile_lowest_ && ring_[next % kRing].empty()) ++next;
    // An empty ring leaves every entry in the pile.
    current_ = next == current_ + kRing ? pile_lowest_ : std::min(next, pile_lowest_);
    if (pile_lowest_ < current_ + kRing) {
      std::size_t kept = 0;
      pile_lowest_ = kNoBucket;
      for (const Piled& e : pile_) {
        if (e.bucket < current_ + kRing) {
          ring_[e.bucket % kRing].push_back(e.entry);
        } else {
          pile_[kept++] = e;
          pile_lowest_ = std::min(pile_lowest_, e.bucket);
        }
      }
      pile_.resize(kept);
    }
  }

 private:
  // 64 priority units: a move's reduced cost is at most about 23 (a diagonal into a cell of
  // cost 252 with the default cost rule), so the ring holds the open entries of most searches;
  // the rest wait in the pile. The ring keeps up to kKeptBucketCapacity entries a bucket
  // between searches.
  static constexpr std::uint64_t kRing = 256;
  static constexpr std::size_t kKeptBucketCapacity = 256;
  static constexpr std::uint64_t kNoBucket = std::numeric_limits<std::uint64_t>::max();
  struct Piled {
    Entry entry;
    std::uint64_t bucket;
  };

  std::vector<std::vector<Entry>> ring_ = std::vector<std::vector<Entry>>(kRing);
  std::vector<Piled> pile_;
  std::uint64_t pile_lowest_ = kNoBucket;  // the pile's lowest bucket
  std::uint64_t current_ = 0;              // the bucket entries leave from
};

// --- BucketQueue: first in, first out within a bucket ---------------------------------------

struct BucketEntry {
  double cost;  // the label it was pushed with: stale once the cell's label is lower
  std::uint32_t slot;
};
// The same for labels kept as floats (the search that meets in the middle): 8 bytes, not 16.
struct FloatBucketEntry {
  float cost;
  std::uint32_t slot;
};

template <class Entry = BucketEntry>
class BucketQueue {
 public:
  static constexpr double kWidth = BucketRing<Entry>::kWidth;

  void clear() {
    ring_.clear();
    read_ = 0;
    size_ = 0;
  }
  // `priority` >= 0; one below the current bucket's edge (rounding) joins the current bucket.
  void push(double priority, const Entry& entry) {
    ++size_;
    ring_.file(std::max(BucketRing<Entry>::bucketOf(priority), ring_.current()), entry);
  }
  // The next live entry into `next` (stale ones, that `stale` finds, are dropped on the way);
  // false when there is none.
  template <class Stale>
  bool pop(Entry& next, const Stale& stale) {
    if (!advance(stale)) return false;
    next = ring_.currentBucket()[read_++];
    --size_;
    return true;
  }
  // A lower bound of every live entry's priority: the lower edge of the lowest bucket that
  // holds one; false when there is none.
  template <class Stale>
  bool lowerBound(double& bound, const Stale& stale) {
    if (!advance(stale)) return false;
    bound = static_cast<double>(ring_.current()) * kWidth;
    return true;
  }

 private:
  // Moves to the first live entry, from the current bucket on; false when none is left.
  template <class Stale>
  bool advance(const Stale& stale) {
    for (;;) {
      std::vector<Entry>& bucket = ring_.currentBucket();
      while (read_ < bucket.size() && stale(bucket[read_])) {
        ++read_;
        --size_;
      }
      if (read_ < bucket.size()) return true;
      ring_.releaseCurrent();
      read_ = 0;
      if (size_ == 0) return false;
      ring_.advance();
    }
  }

  BucketRing<Entry> ring_;
  std::size_t read_ = 0;  // the next entry of the current bucket
  std::size_t size_ = 0;  // entries not yet left, stale ones included
};

// --- OrderedBucketQueue: the lowest bucket in a heap, entries leave in SearchEntry's order --

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

class OrderedBucketQueue {
 public:
  void clear() {
    heap_.clear();
    ring_.clear();
    outside_heap_ = 0;
  }
  void push(const SearchEntry& entry) {
    const std::uint64_t bucket = BucketRing<SearchEntry>::bucketOf(entry.priority);
    if (bucket <= ring_.current()) {
      heap_.push(SearchHeap::itemOf(entry));
      return;
    }
    ++outside_heap_;
    ring_.file(bucket, entry);
  }
  // The next entry into `next`; false when there is none. Entries that `stale` finds out of
  // date (a cheaper label came since) may be dropped on the way: they would be skipped anyway.
  template <class Stale>
  bool pop(SearchEntry& next, const Stale& stale) {
    while (heap_.empty()) {
      if (outside_heap_ == 0) return false;
      refill(stale);
    }
    next = SearchHeap::entryOf(heap_.pop());
    return true;
  }

 private:
  // Moves the next non-empty bucket, less its stale entries, into the (empty) heap.
  template <class Stale>
  void refill(const Stale& stale) {
    ring_.advance();
    std::vector<SearchEntry>& bucket = ring_.currentBucket();
    outside_heap_ -= bucket.size();
    for (const SearchEntry& e : bucket)
      if (!stale(e)) heap_.append(SearchHeap::itemOf(e));
    heap_.heapify();
    ring_.releaseCurrent();
  }

  SearchHeap heap_;
  BucketRing<SearchEntry> ring_;
  std::size_t outside_heap_ = 0;  // entries in the ring and the pile
};

}  // namespace detail
}  // namespace eaci
