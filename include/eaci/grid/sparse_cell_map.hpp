// A 32-bit value per cell of a window whose memory and time grow with the cells given a value,
// not with the window: the window is cut into blocks of 16 x 16 cells, and a block's values
// exist only once one of its cells is written. The colony's region numbers its cells with one
// (ColonyRegion): a route across the map has a bounding box as large as the map, while the
// cells near the route are a thin band of it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_window.hpp"

namespace eaci {

class SparseCellMap {
 public:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  // Every cell of `window` kNone again; the memory is kept for the next window.
  void reset(const CellWindow& window) {
    window_ = window;
    block_cols_ = (window.cols + kBlockSide - 1) >> kBlockShift;
    const int block_rows = (window.rows + kBlockSide - 1) >> kBlockShift;
    block_of_.assign(static_cast<std::size_t>(block_rows) * static_cast<std::size_t>(block_cols_), kNone);
    values_.clear();
  }

  // The value of cell `c`: kNone outside the window or where none was written.
  std::uint32_t get(Cell c) const {
    if (!window_.contains(c)) return kNone;
    const std::uint32_t block = block_of_[blockSlot(c)];
    return block == kNone ? kNone : values_[static_cast<std::size_t>(block) * kBlockCells + cellInBlock(c)];
  }

  // The value of cell `c` (in the window) to write; its block is made (every value kNone) on
  // the first write to it.
  std::uint32_t& at(Cell c) {
    std::uint32_t& block = block_of_[blockSlot(c)];
    if (block == kNone) {
      block = static_cast<std::uint32_t>(values_.size() / kBlockCells);
      values_.resize(values_.size() + kBlockCells, kNone);
    }
    return values_[static_cast<std::size_t>(block) * kBlockCells + cellInBlock(c)];
  }

  // Values held: kBlockCells per block made (for tests and memory accounting).
  std::size_t valuesHeld() const { return values_.size(); }

  static constexpr int kBlockShift = 4;
  static constexpr int kBlockSide = 1 << kBlockShift;
  static constexpr std::size_t kBlockCells = std::size_t{kBlockSide} * kBlockSide;

 private:
  std::size_t blockSlot(Cell c) const {
    return static_cast<std::size_t>((c.row - window_.row0) >> kBlockShift) * static_cast<std::size_t>(block_cols_) +
           static_cast<std::size_t>((c.col - window_.col0) >> kBlockShift);
  }
  std::size_t cellInBlock(Cell c) const {
    return static_cast<std::size_t>((c.row - window_.row0) & (kBlockSide - 1)) * kBlockSide +
           static_cast<std::size_t>((c.col - window_.col0) & (kBlockSide - 1));
  }

  CellWindow window_;
  int block_cols_ = 0;
  std::vector<std::uint32_t> block_of_;  // per block of the window: its first value / kBlockCells, or kNone
  std::vector<std::uint32_t> values_;    // the blocks made, kBlockCells values each, row-major in the block
};

}  // namespace eaci
