// The labels of a search over (cell, heading) states (search/heading_search.hpp), 8 per cell,
// in about the memory of the labels of a search over cells (11 bytes per cell):
// - per cell 12 bytes, in a zero-filled buffer whose pages the system maps only where the
//   search writes: 4 bits per settled state (what the route back needs: the heading of the
//   state it was reached from), the cost and heading of the cell's first settled state (for
//   the dominance test below), and the number of the cell's open block;
// - an open block (8 costs and 8 headings) only while the cell has open states (labelled, not
//   settled); it goes back to a free list when its last open state settles, so the blocks in
//   use follow the search's frontier, not the area it has covered.
// Whole-map arrays of 8 cost labels per cell would take 8 x the 11 bytes per cell of A*'s.
//
// Dominance: a state (c, h) of cost g can do no better than the cell's first settled state
// (c, h0) of cost g0 when g0 + the price of turning from h0 to h <= g (whatever the next move,
// turning from h0 to it costs at most that turn plus turning from h to it). The search neither
// labels nor expands such states; with turn_cost 0 every state after a cell's first is one, and
// the search settles one state per cell, as A* does. g0 is kept as a float rounded up, so the
// test only ever errs towards keeping a state.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <vector>

#include "eaci/grid/moves.hpp"

namespace eaci {
namespace detail {

class HeadingLabels {
 public:
  static constexpr int kHeadings = 8;
  static constexpr unsigned kFromStart = kHeadings;  // the start, which has no heading

  // Room for `cells` cells, no state labelled.
  explicit HeadingLabels(std::size_t cells)
      : cells_(static_cast<CellWord*>(std::calloc(cells == 0 ? 1 : cells, sizeof(CellWord)))) {
    if (!cells_) throw std::bad_alloc();
  }

  bool settled(std::uint32_t cell, int heading) const { return nibble(cell, heading) != 0; }
  // Whether the state (cell, heading) at `cost` can do no better than the cell's first settled
  // state; `turn_price[k]`: the price of turning by k 45-degree steps.
  bool dominated(std::uint32_t cell, int heading, double cost, const double* turn_price) const {
    const CellWord& w = cells_[cell];
    if (w.settled == 0) return false;
    return static_cast<double>(w.first_cost) + turn_price[turnSteps(static_cast<int>(w.block_and_first >> kBlockBits), heading)] <= cost;
  }
  // The heading of the state a settled state was reached from, or kFromStart.
  unsigned settledFrom(std::uint32_t cell, int heading) const { return nibble(cell, heading) - 1; }

  // An open state's cost; +infinity when it has no label (never reached, or settled).
  double cost(std::uint32_t cell, int heading) const {
    const std::uint32_t number = cells_[cell].block_and_first & kBlockMask;
    return number == 0 ? kNone : blocks_[number - 1].cost[heading];
  }
  // Labels the (unsettled) state with `cost`, reached from `from`, unless its label is as cheap
  // or cheaper; true when it did.
  bool lower(std::uint32_t cell, int heading, double cost, unsigned from) {
    CellWord& w = cells_[cell];
    if ((w.block_and_first & kBlockMask) == 0) w.block_and_first |= openBlock();
    Block& block = blocks_[(w.block_and_first & kBlockMask) - 1];
    if (cost >= block.cost[heading]) return false;
    if (block.cost[heading] == kNone) ++block.open;
    block.cost[heading] = cost;
    block.from[heading] = static_cast<std::uint8_t>(from);
    return true;
  }
  // Settles an open state: its label becomes the 4 bits the route back reads.
  void settle(std::uint32_t cell, int heading) {
    CellWord& w = cells_[cell];
    const std::uint32_t number = w.block_and_first & kBlockMask;
    Block& block = blocks_[number - 1];
    if (w.settled == 0) {  // the cell's first
      w.first_cost = roundedUp(block.cost[heading]);
      w.block_and_first |= static_cast<std::uint32_t>(heading) << kBlockBits;
    }
    w.settled |= (static_cast<std::uint32_t>(block.from[heading]) + 1u) << (4 * heading);
    block.cost[heading] = kNone;
    if (--block.open == 0) {
      free_.push_back(number);
      w.block_and_first &= ~kBlockMask;
    }
  }

  // Most blocks open at once (each sizeof(Block) = 80 bytes).
  std::size_t blocksMade() const { return blocks_.size(); }

 private:
  static constexpr double kNone = std::numeric_limits<double>::infinity();
  // The open block's number in the low bits (0: none, else 1 + its index in blocks_; fewer
  // than 2^29 cells, so fewer blocks), the first settled state's heading in the top 3.
  static constexpr unsigned kBlockBits = 29;
  static constexpr std::uint32_t kBlockMask = (std::uint32_t{1} << kBlockBits) - 1;
  struct CellWord {
    std::uint32_t settled;          // 4 bits per heading: 0 not settled, else 1 + the heading it came from
    std::uint32_t block_and_first;  // see kBlockBits
    float first_cost;               // the first settled state's cost, rounded up
  };
  static float roundedUp(double cost) {
    const float f = static_cast<float>(cost);
    return static_cast<double>(f) >= cost ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
  }
  struct Block {
    double cost[kHeadings];
    std::uint8_t from[kHeadings];
    int open;  // labelled states not settled
  };

  unsigned nibble(std::uint32_t cell, int heading) const { return (cells_[cell].settled >> (4 * heading)) & 0xFu; }
  std::uint32_t openBlock() {
    std::uint32_t number;
    if (!free_.empty()) {
      number = free_.back();
      free_.pop_back();
    } else {
      blocks_.emplace_back();
      number = static_cast<std::uint32_t>(blocks_.size());
    }
    Block& block = blocks_[number - 1];
    for (double& c : block.cost) c = kNone;
    block.open = 0;
    return number;
  }

  struct Free {
    void operator()(CellWord* p) const { std::free(p); }
  };
  std::unique_ptr<CellWord[], Free> cells_;
  std::vector<Block> blocks_;
  std::vector<std::uint32_t> free_;
};

}  // namespace detail
}  // namespace eaci
