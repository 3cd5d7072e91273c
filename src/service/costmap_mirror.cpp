#include "costmap_mirror.hpp"

#include <algorithm>
#include <cstring>

namespace eaci_service {
namespace {

bool sameInterpretation(const eaci::CellInterpretation& a, const eaci::CellInterpretation& b) {
  return a.lethal_cost == b.lethal_cost && a.unknown_value == b.unknown_value && a.unknown == b.unknown &&
         a.graded == b.graded;
}

}  // namespace

bool CostmapMirror::sameSetting(const CostmapView& costmap, const eaci::CellInterpretation& interpretation,
                                bool allow_corner_cutting, eaci::CostRule rule) const {
  const eaci::MapFrame& a = copy_.frame;
  const eaci::MapFrame& b = costmap.frame;
  return made_ && a.width == b.width && a.height == b.height && a.resolution == b.resolution && a.origin == b.origin &&
         copy_.order == costmap.order && sameInterpretation(interpretation_, interpretation) &&
         grid_.allowCornerCutting() == allow_corner_cutting && grid_.costRule().neutral_cost == rule.neutral_cost &&
         grid_.costRule().cost_factor == rule.cost_factor;
}

void CostmapMirror::beginAfresh(const CostmapView& costmap, const eaci::CellInterpretation& interpretation,
                                bool allow_corner_cutting, eaci::CostRule rule) {
  made_ = false;
  rows_made_ = 0;
  opened_.clear();
  copy_.frame = costmap.frame;
  copy_.order = costmap.order;
  copy_.cells.resize(costmap.cellCount());  // keeps its memory when large enough
  interpretation_ = interpretation;
  cell_byte_ = eaci::CostGrid::cellByteTable(interpretation);
  grid_.reset(costmap.frame.width, costmap.frame.height, allow_corner_cutting, rule);
  made_ = true;
}

bool CostmapMirror::makeRows(const CostmapView& costmap, eaci::StopPoll& poll) {
  const int width = costmap.frame.width, height = costmap.frame.height;
  for (; rows_made_ < height; ++rows_made_) {
    if (poll.stopped()) return false;
    const std::size_t at = static_cast<std::size_t>(rows_made_) * static_cast<std::size_t>(width);
    std::memcpy(copy_.cells.data() + at, costmap.cells + at, static_cast<std::size_t>(width));
    const int row = gridRow(rows_made_);
    grid_.assignRect(view(), cell_byte_, row, row + 1, 0, width);
    poll.tick(static_cast<std::size_t>(width));
  }
  return true;
}

bool CostmapMirror::syncRow(const CostmapView& costmap, int y, int x0, int x1) {
  const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(costmap.frame.width) +
                         static_cast<std::size_t>(x0);
  const std::size_t count = static_cast<std::size_t>(x1 - x0);
  if (std::memcmp(costmap.cells + at, copy_.cells.data() + at, count) == 0) return false;
  std::memcpy(copy_.cells.data() + at, costmap.cells + at, count);
  const int row = gridRow(y);
  grid_.assignRect(view(), cell_byte_, row, row + 1, x0, x1);
  return true;
}

bool CostmapMirror::syncRows(const CostmapView& costmap, int y0, int y1, int x0, int x1, eaci::StopPoll& poll,
                             Sync& done) {
  for (int y = y0; y < y1; ++y) {
    if (poll.stopped()) {
      done.stopped = true;
      return false;
    }
    done.rows_changed += syncRow(costmap, y, x0, x1) ? 1 : 0;
    ++done.rows_read;
    poll.tick(static_cast<std::size_t>(x1 - x0));
  }
  return true;
}

CostmapMirror::Sync CostmapMirror::sync(const CostmapView& costmap, const CostmapChanges& changes,
                                        const eaci::CellInterpretation& interpretation, bool allow_corner_cutting,
                                        eaci::CostRule rule, const std::function<bool()>& should_stop) {
  Sync done;
  const int width = costmap.frame.width, height = costmap.frame.height;
  eaci::StopPoll poll(should_stop, 0, kBytesBetweenStopChecks);  // ticked with the bytes of each row read
  try {
    copy_.frame_id = costmap.frame_id;
    const bool same = sameSetting(costmap, interpretation, allow_corner_cutting, rule);
    if (!same || rows_made_ < height) {  // a new copy, or one a stop left part made
      if (!same) {
        beginAfresh(costmap, interpretation, allow_corner_cutting, rule);
      } else {  // the rows made before the stop, compared: nothing is known of what changed since
        restore();
        syncRows(costmap, 0, rows_made_, 0, width, poll, done);
      }
      const int before = rows_made_;
      done.stopped = done.stopped || !makeRows(costmap, poll);
      done.afresh = true;
      done.rows_read = static_cast<std::size_t>(rows_made_);
      done.rows_changed += static_cast<std::size_t>(rows_made_ - before);
      return done;
    }
  } catch (...) {
    clear();
    throw;
  }
  restore();
  if (!changes.known) {
    syncRows(costmap, 0, height, 0, width, poll, done);
    return done;
  }
  for (const BufferRect& rect : changes.rects) {
    const int x0 = std::max(0, rect.x0), x1 = std::min(width, rect.x1);
    const int y0 = std::max(0, rect.y0), y1 = std::min(height, rect.y1);
    if (x0 < x1 && !syncRows(costmap, y0, y1, x0, x1, poll, done)) return done;
  }
  const std::size_t audit_rows =
      std::min(static_cast<std::size_t>(height), std::max<std::size_t>(1, audit_bytes_ / static_cast<std::size_t>(width)));
  for (std::size_t k = 0; k < audit_rows; ++k) {
    if (audit_next_ >= height) audit_next_ = 0;
    if (syncRow(costmap, audit_next_++, 0, width)) {
      ++done.rows_missed;
      ++done.rows_changed;
    }
  }
  done.rows_read += audit_rows;
  return done;
}

void CostmapMirror::open(eaci::Cell c, std::uint8_t value) {
  const std::size_t at = copy_.bufferIndex(c);
  opened_.push_back({at, copy_.cells[at]});
  copy_.cells[at] = value;
  const std::uint8_t byte = cell_byte_[value];
  if (byte == eaci::CostGrid::kObstacle) grid_.setBlocked(c, true);
  else grid_.setCost(c, byte);
}

void CostmapMirror::restore() {
  for (auto it = opened_.rbegin(); it != opened_.rend(); ++it) {
    copy_.cells[it->buffer_index] = it->value;
    const auto width = static_cast<std::size_t>(copy_.frame.width);
    const int row = gridRow(static_cast<int>(it->buffer_index / width));
    const int col = static_cast<int>(it->buffer_index % width);
    grid_.assignRect(view(), cell_byte_, row, row + 1, col, col + 1);
  }
  opened_.clear();
}

void CostmapMirror::clear() {
  made_ = false;
  rows_made_ = 0;
  opened_.clear();
  copy_ = CostmapSnapshot{};
  grid_ = eaci::CostGrid{};
}

}  // namespace eaci_service
