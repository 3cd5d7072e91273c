// Search labels kept from search to search (GridSearchWorkspace, MeetingSearch): a caller that
// keeps them allocates once per map size, and a search costs only the cells it labels. Each
// label carries the number of the search that wrote it (a 2-byte generation stamp), so only
// the stamps are ever cleared: on allocation, and once per 65 535 searches.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>

namespace eaci {
namespace detail {

// One set of labels as a search sees it: a slot's cost and move belong to this search when its
// stamp is this search's generation; generation 0 is no search's. `Cost`: how a cost is kept,
// double (A*: exact sums) or float (the search that meets in the middle: half the memory; a
// label is the sum rounded to float at every move, kept(), so that the search compares and
// stores the same numbers).
template <class Cost = double>
struct StampedLabels {
  Cost* costs;
  std::uint8_t* moves;
  std::uint16_t* generations;
  std::uint16_t generation;
  double cost(std::uint32_t slot) const {
    return generations[slot] == generation ? static_cast<double>(costs[slot]) : std::numeric_limits<double>::infinity();
  }
  // A route cost as these labels keep it.
  static double kept(double c) { return static_cast<double>(static_cast<Cost>(c)); }
  std::uint8_t moveInto(std::size_t slot) const { return moves[slot]; }
  // `c` as kept() gives it.
  void label(std::uint32_t slot, double c, std::uint8_t move) {
    costs[slot] = static_cast<Cost>(c);
    moves[slot] = move;
    generations[slot] = generation;
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
    if (++generation_ == 0) {  // the numbers wrapped round: forget every label
      for (Arrays& set : sets_) std::fill(set.generations.get(), set.generations.get() + capacity_, std::uint16_t{0});
      generation_ = 1;
    }
  }
  // Set `set`'s labels of the current search.
  StampedLabels<Cost> of(int set) const {
    const Arrays& a = sets_[static_cast<std::size_t>(set)];
    return StampedLabels<Cost>{a.costs.get(), a.moves.get(), a.generations.get(), generation_};
  }

 private:
  struct FreeDeleter {
    void operator()(void* memory) const { std::free(memory); }
  };
  struct Arrays {
    std::unique_ptr<Cost[]> costs;
    std::unique_ptr<std::uint8_t[]> moves;
    std::unique_ptr<std::uint16_t[], FreeDeleter> generations;
    // Every label of generation 0: no search's. The stamps come zeroed from calloc, which
    // takes fresh pages from the system for a map-sized array without writing them, and
    // costs and moves are not initialised: a page of any of them is resident only once a
    // search labels a cell on it (a short route on a large map costs the pages it touches).
    void allocate(std::size_t slots) {
      generations.reset();  // the old buffers go first
      costs.reset();
      moves.reset();
      generations.reset(static_cast<std::uint16_t*>(std::calloc(slots, sizeof(std::uint16_t))));
      if (!generations) throw std::bad_alloc();
      costs.reset(new Cost[slots]);
      moves.reset(new std::uint8_t[slots]);
    }
  };
  std::array<Arrays, Sets> sets_;
  std::size_t capacity_ = 0;
  std::uint16_t generation_ = 0;
};

}  // namespace detail
}  // namespace eaci
