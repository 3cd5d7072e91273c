// The labels of the states a search has reached but not settled (its open states), in a hash
// table that holds only them: a label is taken out when its state settles. A search over many
// states per cell (search/heading_search.hpp: 8 per cell) keeps labels only for its frontier,
// which grows with the frontier's length, not with the map's area.
//
// Open addressing, linear probing, deletion by shifting the entries behind back (no
// tombstones), a power-of-two capacity at most half full.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace eaci {
namespace detail {

class OpenStateLabels {
 public:
  // No state has this number: the mark of an empty entry.
  static constexpr std::uint32_t kNoState = std::numeric_limits<std::uint32_t>::max();

  // Forgets every label; keeps the memory.
  void clear() {
    for (Entry& e : entries_) e.state = kNoState;
    size_ = 0;
  }
  std::size_t size() const { return size_; }
  // Entries allocated (each of sizeof(Entry) = 16 bytes).
  std::size_t capacity() const { return entries_.size(); }

  // The state's label cost; +infinity when it has none (never reached, or settled).
  double cost(std::uint32_t state) const {
    if (entries_.empty()) return std::numeric_limits<double>::infinity();
    for (std::size_t i = home(state);; i = (i + 1) & mask_) {
      const Entry& e = entries_[i];
      if (e.state == state) return e.cost;
      if (e.state == kNoState) return std::numeric_limits<double>::infinity();
    }
  }

  // Labels `state` with `cost` and `from` when it has no label or a dearer one; false (and no
  // change) when its label is as cheap or cheaper.
  bool lower(std::uint32_t state, double cost, std::uint8_t from) {
    if (2 * (size_ + 1) > entries_.size()) grow();
    for (std::size_t i = home(state);; i = (i + 1) & mask_) {
      Entry& e = entries_[i];
      if (e.state == state) {
        if (cost >= e.cost) return false;
        e.cost = cost;
        e.from = from;
        return true;
      }
      if (e.state == kNoState) {
        e = Entry{cost, state, from};
        ++size_;
        return true;
      }
    }
  }

  // Takes the state's label out and returns its `from`; the state must have a label.
  std::uint8_t take(std::uint32_t state) {
    std::size_t i = home(state);
    while (entries_[i].state != state) i = (i + 1) & mask_;
    const std::uint8_t from = entries_[i].from;
    // Shift back every entry of the run behind i whose home does not lie between i and it.
    for (std::size_t j = (i + 1) & mask_;; j = (j + 1) & mask_) {
      const Entry& e = entries_[j];
      if (e.state == kNoState) break;
      const std::size_t h = home(e.state);
      const bool stays = i <= j ? (i < h && h <= j) : (i < h || h <= j);
      if (stays) continue;
      entries_[i] = e;
      i = j;
    }
    entries_[i].state = kNoState;
    --size_;
    return from;
  }

 private:
  struct Entry {
    double cost;
    std::uint32_t state;
    std::uint8_t from;
  };

  std::size_t home(std::uint32_t state) const {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(state) * 0x9E3779B97F4A7C15ull) >> shift_) & mask_;
  }
  void grow() {
    std::vector<Entry> old;
    old.swap(entries_);
    const std::size_t capacity = old.empty() ? 1024 : 2 * old.size();
    entries_.assign(capacity, Entry{0.0, kNoState, 0});
    mask_ = capacity - 1;
    shift_ = 64;
    for (std::size_t c = capacity; c > 1; c >>= 1) --shift_;
    size_ = 0;
    for (const Entry& e : old)
      if (e.state != kNoState) lower(e.state, e.cost, e.from);
  }

  std::vector<Entry> entries_;
  std::size_t mask_ = 0;
  unsigned shift_ = 64;  // 64 - log2(capacity): the top bits of the product pick the entry
  std::size_t size_ = 0;
};

}  // namespace detail
}  // namespace eaci
