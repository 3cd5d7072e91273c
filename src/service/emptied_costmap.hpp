// A costmap that costmap_2d has emptied and not filled again yet, and what to plan on instead.
//
// costmap_2d empties a costmap when it resizes it (the static layer took a larger map from SLAM:
// gmapping grows its map every few seconds) or clears it (move_base's ~clear_costmaps): every
// cell then holds the default value -- FREE_SPACE, or NO_INFORMATION with the costmap's own
// track_unknown_space -- until the costmap's next update fills it, up to 1 / update_frequency
// later. A plan in between sees no wall at all, and both navfn and a plain planner route
// straight through walls (measured through move_base on a growing map: docs/notebook/2026-12-03-a-map-that-grows.md). The planning service keeps the last costmap that was filled and plans on a costmap
// emptied by a resize as that one showed it, placed into the new frame (a grown map holds the
// old one), while that one is recent.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "costmap_snapshot.hpp"
#include "costmap_view.hpp"

namespace eaci_service {

// True when every cell holds the same value (and there is at least one cell): what costmap_2d
// leaves in a costmap it has emptied. Stops at the first cell that differs.
bool isUniform(const CostmapView& costmap);
inline bool isUniform(const CostmapSnapshot& costmap) { return isUniform(CostmapView::of(costmap)); }

// `last` placed into `frame`: each cell of `frame` that a cell of `last` lies on takes that
// cell's value, every other cell `fill`. Null when the resolutions differ or the origins are not
// a whole number of cells apart (then nothing of `last` lines up with `frame`'s cells).
std::optional<CostmapSnapshot> placedInto(const CostmapSnapshot& last, const eaci::MapFrame& frame, std::uint8_t fill);

// Decides when to plan on the last filled costmap instead of an emptied one. It keeps no copy:
// the planner's own copy of the last filled costmap (its CostmapMirror) is handed in.
class EmptiedCostmapStandIn {
 public:
  using Clock = std::chrono::steady_clock;
  // The last filled costmap stands in only while it was read at most `max_age` ago.
  explicit EmptiedCostmapStandIn(Clock::duration max_age) : max_age_(max_age) {}

  // Called with each plan's costmap before anything else reads it, and the last filled costmap
  // the planner holds (null: none) with when it was read. Stands in only for a costmap that
  // costmap_2d has emptied by a resize: uniform, and of another size, origin or resolution than
  // the last filled one (a costmap of the same frame that is uniform -- cleared, or a world
  // with nothing in it -- is planned on as it is), and only with data read at most max_age
  // before `now`. Then: the held one placed into the new frame, to plan on instead, and `said`
  // (else left alone) says so. Throws std::bad_alloc when the placed copy does not fit.
  std::optional<CostmapSnapshot> standIn(const CostmapView& costmap, const CostmapSnapshot* last_filled,
                                         Clock::time_point last_filled_read, Clock::time_point now, std::string& said);
  // The costmap of the last standIn() was filled (not uniform).
  bool lastWasFilled() const { return filled_; }

 private:
  const Clock::duration max_age_;
  bool filled_ = false;
};

}  // namespace eaci_service
