// The open list of the search that meets in the middle (GridSearchWorkspace::
// cheapestRouteBetween): buckets of priority width kWidth and nothing else, no heap. Within a
// bucket entries leave first in, first out, so a cell may leave before a cheaper label for it
// arrives from a cell of the same bucket; the search then labels it again and it leaves again
// (a label-correcting search, as in Delta-stepping: Meyer & Sanders, J. Algorithms 49, 2003).
// The labels a search ends with are still exact: a cell whose cost is below the lowest bucket
// still open keeps its label (the cheapest route to it ran through cells that all left the
// list with their final labels). Bucket edges are the lower bounds the search stops on.
//
// What it saves over SearchQueue: the heap (a sift per entry) and the total order among
// entries of one bucket; what it costs: a few cells labelled twice (the narrower the buckets,
// the fewer). The order is fixed by the pushes alone, so a search gives the same labels on
// every run.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace eaci {
namespace detail {

struct BucketEntry {
  double cost;  // the label it was pushed with: stale once the cell's label is lower
  std::uint32_t slot;
};

class BucketQueue {
 public:
  static constexpr double kWidth = 1.0 / 4.0;

  void clear() {
    for (auto& bucket : ring_) bucket.clear();
    beyond_.clear();
    beyond_lowest_ = kNoBucket;
    current_ = 0;
    read_ = 0;
    size_ = 0;
  }
  // `priority` >= 0; one below the current bucket's edge (rounding) joins the current bucket.
  void push(double priority, const BucketEntry& entry) {
    const std::uint64_t bucket = std::max(bucketOf(priority), current_);
    ++size_;
    if (bucket < current_ + kRing) {
      ring_[bucket % kRing].push_back(entry);
    } else {
      beyond_.push_back({entry, bucket});
      beyond_lowest_ = std::min(beyond_lowest_, bucket);
    }
  }
  // The next live entry into `next` (stale ones, that `stale` finds, are dropped on the way);
  // false when there is none.
  template <class Stale>
  bool pop(BucketEntry& next, const Stale& stale) {
    if (!advance(stale)) return false;
    next = ring_[current_ % kRing][read_++];
    --size_;
    return true;
  }
  // A lower bound of every live entry's priority: the lower edge of the lowest bucket that
  // holds one; false when there is none.
  template <class Stale>
  bool lowerBound(double& bound, const Stale& stale) {
    if (!advance(stale)) return false;
    bound = static_cast<double>(current_) * kWidth;
    return true;
  }

 private:
  // 64 priority units: a move's reduced cost is at most about 23 (a diagonal into a cell of
  // cost 252 with the default cost rule), so the ring holds the open entries of most searches;
  // the rest wait in a pile. The ring keeps up to kKeptBucketCapacity entries a bucket between
  // searches (256 KiB).
  static constexpr std::uint64_t kRing = 256;
  static constexpr std::size_t kKeptBucketCapacity = 256;
  static constexpr std::uint64_t kNoBucket = std::numeric_limits<std::uint64_t>::max();
  struct FarEntry {
    BucketEntry entry;
    std::uint64_t bucket;
  };
  static std::uint64_t bucketOf(double priority) {
    return static_cast<std::uint64_t>(std::min(std::max(priority, 0.0) / kWidth, 4.0e18));
  }

  // Moves to the first live entry, from the current bucket on; false when none is left.
  template <class Stale>
  bool advance(const Stale& stale) {
    for (;;) {
      std::vector<BucketEntry>& bucket = ring_[current_ % kRing];
      while (read_ < bucket.size() && stale(bucket[read_])) {
        ++read_;
        --size_;
      }
      if (read_ < bucket.size()) return true;
      // The bucket is done: give a large one's memory back and go on to the next non-empty one.
      if (bucket.capacity() > kKeptBucketCapacity) std::vector<BucketEntry>().swap(bucket);
      else bucket.clear();
      read_ = 0;
      if (size_ == 0) return false;
      std::uint64_t next = current_ + 1;
      while (next < current_ + kRing && next < beyond_lowest_ && ring_[next % kRing].empty()) ++next;
      // An empty ring leaves every entry in the pile.
      current_ = next == current_ + kRing ? beyond_lowest_ : std::min(next, beyond_lowest_);
      if (beyond_lowest_ < current_ + kRing) {  // the pile's entries that the ring now covers join it
        std::size_t kept = 0;
        beyond_lowest_ = kNoBucket;
        for (const FarEntry& e : beyond_) {
          if (e.bucket < current_ + kRing) {
            ring_[e.bucket % kRing].push_back(e.entry);
          } else {
            beyond_[kept++] = e;
            beyond_lowest_ = std::min(beyond_lowest_, e.bucket);
          }
        }
        beyond_.resize(kept);
      }
    }
  }

  std::vector<std::vector<BucketEntry>> ring_ = std::vector<std::vector<BucketEntry>>(kRing);
  std::vector<FarEntry> beyond_;
  std::uint64_t beyond_lowest_ = kNoBucket;  // the pile's lowest bucket
  std::uint64_t current_ = 0;                // the bucket entries leave from
  std::size_t read_ = 0;                     // the next entry of the current bucket
  std::size_t size_ = 0;                     // entries not yet left, stale ones included
};

}  // namespace detail
}  // namespace eaci
