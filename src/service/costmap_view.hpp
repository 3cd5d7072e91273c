// A costmap's cells as the caller holds them, borrowed for one plan, and what changed in them
// since the caller's previous plan.
//
// The move_base plugin plans under the costmap's own lock (move_base already holds it around
// makePlan; the lock is recursive), so it hands the planning service the costmap's char map
// itself, not a copy: the service reads only what it needs (CostmapMirror). costmap_2d knows
// where it rewrites its cells on each update; the plugin collects those rectangles between two
// plans (CostmapChanges), so a plan on a costmap that changed in a few places reads only those.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "costmap_snapshot.hpp"

namespace eaci_service {

struct CostmapView {
  const std::uint8_t* cells = nullptr;  // frame.width x frame.height costs, valid and unchanged for the call
  eaci::MapFrame frame;
  std::string frame_id;
  eaci::RowOrder order = eaci::RowOrder::kBottomFirst;
  // How many cells `cells` holds when the caller knows (a copy's size), checked against the
  // frame; kUnchecked: the caller vouches for width x height (a costmap_2d char map).
  static constexpr std::size_t kUnchecked = static_cast<std::size_t>(-1);
  std::size_t cells_held = kUnchecked;

  static CostmapView of(const CostmapSnapshot& costmap) {
    return {costmap.cells.data(), costmap.frame, costmap.frame_id, costmap.order, costmap.cells.size()};
  }
  std::size_t cellCount() const {
    return static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height);
  }
};

// A rectangle of buffer cells: columns [x0, x1) of buffer rows [y0, y1) (costmap_2d's map
// coordinates: row 0 is the one at the origin for a bottom-first costmap).
struct BufferRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// What changed in a costmap since the previous plan on it, as far as its keeper knows.
struct CostmapChanges {
  // False: not known (the planner node's maps, the ~make_plan service without a tracker): the
  // mirror compares every cell with its own copy (one memcmp per row).
  bool known = false;
  // Known: these rectangles hold every cell that changed (none: the costmap is as it was). A
  // new size, origin or resolution is seen from the frame, whatever they say.
  std::vector<BufferRect> rects;

  static CostmapChanges unknown() { return {}; }
  static CostmapChanges none() { return {true, {}}; }
};

}  // namespace eaci_service
