// Where a plan's costmap comes from: the planner's own copy of the caller's costmap
// (CostmapMirror), brought up to it where its keeper says it changed, or, for a costmap
// costmap_2d has just emptied by a resize, the last filled one placed into its frame
// (EmptiedCostmapStandIn). It decides how far the keeper's reports are trusted:
//   - reports taken but never read (a plan refused before it read the costmap: a wrong frame,
//     a bad parameter, the planning turn's wait timed out) are made good by the next read,
//     which compares every row (changesNotRead());
//   - a read of a copy with nothing known of what changed (~make_plan, the node) may leave the
//     copy older than the keeper's later reports assume: the next read compares every row;
//   - a read stopped part-way (the plan's time limit, a cancel) leaves the copy part read: the
//     next read compares every row;
//   - a change the keeper missed (found by the mirror's audit) gets every row compared for the
//     next kDistrustedReads reads, then the reports are trusted again; counted (missedWrites()).
// Used by the plan holding the planning turn, but changesNotRead(), which any thread may call.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "costmap_mirror.hpp"
#include "costmap_snapshot.hpp"
#include "costmap_view.hpp"
#include "emptied_costmap.hpp"

namespace eaci_service {

class CostmapSource {
 public:
  using Clock = std::chrono::steady_clock;
  // Reads after a missed change that compare every row before the reports are trusted again.
  static constexpr int kDistrustedReads = 20;

  struct Settings {
    bool stand_in_for_emptied = false;  // costmap_2d's costmaps: stand in for one emptied by a resize
    double stand_in_max_age = 5.0;      // s: the last filled costmap stands in only while read this recently
  };
  CostmapSource(Settings settings, std::function<void(const std::string&, bool warn)> say);

  struct Read {
    CostmapMirror* mirror = nullptr;  // the copy the plan reads (the start's way out may be opened in it)
    CostmapMirror::Sync synced;
    bool stood_in = false;            // the last filled costmap stands in for an emptied one
  };
  // The copy brought up to `costmap` (every cell valid for the call) as the keeper's `changes`
  // and the trust above allow, read as given; `rolling`: a costmap that moves with the robot
  // (no stand-in). Throws what CostmapMirror::sync throws (the source is then cleared). Asks
  // `should_stop` between blocks of rows: stopped (read.synced.stopped), the copy is part read
  // and the next read compares every row, going on with the rows not yet made.
  Read read(const CostmapView& costmap, const CostmapChanges& changes, const eaci::CellInterpretation& interpretation,
            bool allow_corner_cutting, eaci::CostRule rule, bool rolling, Clock::time_point now,
            const std::function<bool()>& should_stop = {});

  // The changes handed to a plan were not read: the next read compares every row.
  void changesNotRead() noexcept { changes_unread_.store(true); }
  // Changes the keeper missed so far (each distrusted for kDistrustedReads reads).
  std::size_t missedWrites() const { return missed_writes_; }
  // Forgets everything: the next read makes the copy afresh.
  void clear();

 private:
  const Settings settings_;
  const std::function<void(const std::string&, bool)> say_;
  EmptiedCostmapStandIn emptied_;
  CostmapMirror mirror_;                 // the costmap as of the last read
  CostmapMirror stood_in_;               // the last filled costmap placed into an emptied one's frame
  bool mirror_filled_ = false;           // mirror_ holds a filled (not uniform) costmap
  Clock::time_point filled_read_{};      // when mirror_ last read a filled costmap
  bool mirror_behind_ = false;           // mirror_ may be behind what the keeper reports next
  int distrusted_reads_left_ = 0;
  std::size_t missed_writes_ = 0;
  std::string emptied_said_;             // the stand-in's sentence last said
  std::atomic<bool> changes_unread_{false};
};

}  // namespace eaci_service
