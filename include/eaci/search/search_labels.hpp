// Search labels kept from search to search (GridSearchWorkspace, MeetingSearch): a caller that
// keeps them allocates once per map size, and a search costs only the cells it labels. Each
// label carries the number of the search that wrote it (a 12-bit generation, in one 2-byte
// stamp with the label's move), so only the stamps are ever cleared: on allocation, and once
// per 4095 searches.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>

#include "eaci/search/route_back.hpp"

namespace eaci {
namespace detail {

// A label's stamp: the search's generation (1 .. kMaxGeneration; 0 is no search's) in the high
// 12 bits, the move into the cell in the low 4 (kStampNoMove for kNoMove).
constexpr std::uint16_t kMaxGeneration = 0x0FFF;
constexpr std::uint16_t kStampNoMove = 0x0F;

// One set of labels as a search sees it: a slot's cost and move belong to this search when its
// stamp's generation is this search's. `Cost`: how a cost is kept, double (A*: exact sums) or
// float (the search that meets in the middle: half the memory; a label is the sum rounded to
// float at every move, kept(), so that the search compares and stores the same numbers).
template <class Cost = double>
struct StampedLabels {
  Cost* costs;
  std::uint16_t* stamps;
  std::uint16_t generation;
  double cost(std::uint32_t slot) const {
    return (stamps[slot] >> 4) == generation ? static_cast<double>(costs[slot])
                                             : std::numeric_limits<double>::infinity();
  }
  // A route cost as these labels keep it.
  static double kept(double c) { return static_cast<double>(static_cast<Cost>(c)); }
  std::uint8_t moveInto(std::size_t slot) const {
    const auto move = static_cast<std::uint8_t>(stamps[slot] & kStampNoMove);
    return move == kStampNoMove ? kNoMove : move;
  }
  // `c` as kept() gives it; `move` a direction or kNoMove.
  void label(std::uint32_t slot, double c, std::uint8_t move) {
    costs[slot] = static_cast<Cost>(c);
    stamps[slot] = static_cast<std::uint16_t>((generation << 4) | (move == kNoMove ? kStampNoMove : move));
  }
};

// `Sets` sets of label arrays (one per side of a search) numbered by one count of searches.
template <int Sets, class Cost = double>
class KeptLabels {
 public:
  // Room for `slots` labels in every set, none of them this search's. Costs and moves are read
  // only where the stamp says they were written.
  void prepare(std::size_t slots) {
    if (slots > capacity_) {
      for (Arrays& set : sets_) set.allocate(slots);
      capacity_ = slots;
      generation_ = 0;
    }
    if (++generation_ > kMaxGeneration) {  // the numbers wrapped round: forget every label
      for (Arrays& set : sets_) std::fill(set.stamps.get(), set.stamps.get() + capacity_, std::uint16_t{0});
      generation_ = 1;
    }
  }
  // Set `set`'s labels of the current search.
  StampedLabels<Cost> of(int set) const {
    const Arrays& a = sets_[static_cast<std::size_t>(set)];
    return StampedLabels<Cost>{a.costs.get(), a.stamps.get(), generation_};
  }

 private:
  struct FreeDeleter {
    void operator()(void* memory) const { std::free(memory); }
  };
  struct Arrays {
    std::unique_ptr<Cost[]> costs;
    std::unique_ptr<std::uint16_t[], FreeDeleter> stamps;
    // Every label of generation 0: no search's. The stamps come zeroed from calloc, which
    // takes fresh pages from the system for a map-sized array without writing them, and the
    // costs are not initialised: a page of either is resident only once a search labels a
    // cell on it (a short route on a large map costs the pages it touches).
    void allocate(std::size_t slots) {
      stamps.reset();  // the old buffers go first
      costs.reset();
      stamps.reset(static_cast<std::uint16_t*>(std::calloc(slots, sizeof(std::uint16_t))));
      if (!stamps) throw std::bad_alloc();
      costs.reset(new Cost[slots]);
    }
  };
  std::array<Arrays, Sets> sets_;
  std::size_t capacity_ = 0;
  std::uint16_t generation_ = 0;
};

}  // namespace detail
}  // namespace eaci
