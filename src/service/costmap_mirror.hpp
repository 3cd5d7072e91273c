// The planner's own copy of a costmap, kept from plan to plan and brought up to date only where
// the costmap changed (issue #31: plan time that grows with the route, not the map).
//
// It holds the costmap's bytes as they were at the last plan (the stand-in for an emptied
// costmap plans on them, the start's way out is opened in them) and the planners' grid made
// from them (eaci::CostGrid: the interpretation of every byte, row 0 at the top). sync() reads
// the costmap where it changed -- the rectangles its keeper reports, or, when nobody knows,
// every row compared with the copy (a memcmp per row, no interpretation), plus a few rows
// audited round the map in case the keeper missed a change -- and interprets again only the
// rows that differ; the grid numbers each change by row (CostGrid::rowChange),
// so the landmarks are checked again only where it changed (LandmarkCache). A new size,
// origin, resolution, row order, interpretation or move rule makes both afresh (their memory
// is kept when large enough). A sync asks `should_stop` between blocks of rows (a plan's time
// limit counts from the caller's entry, the first copy of a large costmap included): stopped,
// the copy keeps the rows made so far and the next sync, which must then compare every row,
// goes on from there.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "costmap_snapshot.hpp"
#include "costmap_view.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci_service {

class CostmapMirror {
 public:
  // Told what changed, a sync also compares this many bytes of whole rows (at least one row),
  // the next rows each time, round the map: a change its keeper failed to report is found
  // within (cells / kAuditBytes) plans (a few microseconds a plan).
  static constexpr std::size_t kAuditBytes = std::size_t{64} << 10;
  // Bytes read between two questions to a sync's should_stop (about 0.1 ms of copying).
  static constexpr std::size_t kBytesBetweenStopChecks = std::size_t{64} << 10;
  explicit CostmapMirror(std::size_t audit_bytes = kAuditBytes) : audit_bytes_(audit_bytes) {}

  struct Sync {
    bool afresh = false;         // made anew (first plan, a new frame or interpretation)
    std::size_t rows_read = 0;   // buffer rows compared or copied
    std::size_t rows_changed = 0;
    std::size_t rows_missed = 0; // rows the audit found changed that the keeper had not reported
    bool stopped = false;        // should_stop said stop first: the copy is part read, the next sync
                                 // must be told nothing is known (CostmapChanges::unknown())
  };

  // Brings the copy and the grid up to `costmap` (every cell valid), read as `interpretation`
  // with the move and cost rules given. `changes` as its keeper knows them. Throws
  // std::bad_alloc (the mirror is then empty and made afresh by the next sync) and
  // std::invalid_argument for a cost rule the grid refuses.
  Sync sync(const CostmapView& costmap, const CostmapChanges& changes, const eaci::CellInterpretation& interpretation,
            bool allow_corner_cutting, eaci::CostRule rule, const std::function<bool()>& should_stop = {});

  // The costmap's bytes as of the last sync, with the cells open() changed.
  const CostmapSnapshot& costmap() const { return copy_; }
  // The planners' grid of them.
  const eaci::CostGrid& grid() const { return grid_; }
  // A view of the copy as the last sync read it.
  eaci::GridView view() const {
    return eaci::GridView(copy_.cells.data(), copy_.frame.width, copy_.frame.height, copy_.order, interpretation_);
  }

  // Sets cell `c` (row 0 = top) to costmap value `value` in the copy and the grid until
  // restore(), which the next sync does first (the start's way out, for one plan).
  void open(eaci::Cell c, std::uint8_t value);
  void restore();

  // Forgets everything: the next sync makes the mirror afresh.
  void clear();

 private:
  // Sizes the copy and the grid for `costmap`, no row made yet.
  void beginAfresh(const CostmapView& costmap, const eaci::CellInterpretation& interpretation,
                   bool allow_corner_cutting, eaci::CostRule rule);
  // Copies and interprets buffer rows rows_made_ .. the last; false when should_stop said stop first.
  bool makeRows(const CostmapView& costmap, eaci::StopPoll& poll);
  // Copies and interprets columns [x0, x1) of buffer row `y` if they differ from the copy.
  bool syncRow(const CostmapView& costmap, int y, int x0, int x1);
  // syncRow for rows y0 .. y1 - 1, counted in `done` (rows read and changed), `poll` ticked with
  // the bytes of each; false, with done.stopped set, once it says stop.
  bool syncRows(const CostmapView& costmap, int y0, int y1, int x0, int x1, eaci::StopPoll& poll, Sync& done);
  // The grid row (row 0 = top) of buffer row `y` of the copy.
  int gridRow(int y) const { return copy_.order == eaci::RowOrder::kTopFirst ? y : copy_.frame.height - 1 - y; }
  bool sameSetting(const CostmapView& costmap, const eaci::CellInterpretation& interpretation,
                   bool allow_corner_cutting, eaci::CostRule rule) const;

  std::size_t audit_bytes_;
  int audit_next_ = 0;  // the buffer row the next audit starts at
  CostmapSnapshot copy_;
  eaci::CostGrid grid_;
  eaci::CellInterpretation interpretation_;
  std::array<std::uint8_t, 256> cell_byte_{};
  bool made_ = false;
  int rows_made_ = 0;  // buffer rows of the copy made since it was begun afresh (all, once made)
  struct Opened {
    std::size_t buffer_index;
    std::uint8_t value;  // the costmap's value before open()
  };
  std::vector<Opened> opened_;
};

}  // namespace eaci_service
