#include "costmap_source.hpp"

#include <algorithm>
#include <utility>

namespace eaci_service {

CostmapSource::CostmapSource(Settings settings, std::function<void(const std::string&, bool)> say)
    : settings_(settings),
      say_(std::move(say)),
      emptied_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(std::max(0.0, settings.stand_in_max_age)))) {}

CostmapSource::Read CostmapSource::read(const CostmapView& costmap, const CostmapChanges& changes,
                                        const eaci::CellInterpretation& interpretation, bool allow_corner_cutting,
                                        eaci::CostRule rule, bool rolling, Clock::time_point now,
                                        const std::function<bool()>& should_stop) {
  Read read;
  try {
    mirror_.restore();  // the cells opened for the last plan's start, before anything reads the copy
    std::optional<CostmapSnapshot> placed;
    if (settings_.stand_in_for_emptied && !rolling) {
      std::string said;
      placed = emptied_.standIn(costmap, mirror_filled_ ? &mirror_.costmap() : nullptr, filled_read_, now, said);
      if (placed && said != emptied_said_) say_(said, false);
      emptied_said_ = placed ? said : "";
    }
    if (placed) {
      read.mirror = &stood_in_;
      read.stood_in = true;
      read.synced = stood_in_.sync(CostmapView::of(*placed), CostmapChanges::unknown(), interpretation,
                                   allow_corner_cutting, rule, should_stop);
      mirror_behind_ = true;  // mirror_ missed the changes the keeper reported with this costmap
      return read;
    }
    const bool compare_all =
        changes_unread_.exchange(false) || mirror_behind_ || distrusted_reads_left_ > 0 || !changes.known;
    read.mirror = &mirror_;
    read.synced = mirror_.sync(costmap, compare_all ? CostmapChanges::unknown() : changes, interpretation,
                               allow_corner_cutting, rule, should_stop);
    if (read.synced.stopped) {  // part read: the next read compares every row
      changes_unread_.store(true);
      return read;
    }
    if (distrusted_reads_left_ > 0) --distrusted_reads_left_;
    if (read.synced.rows_missed > 0) {
      ++missed_writes_;
      distrusted_reads_left_ = kDistrustedReads;
      say_("the costmap changed in " + std::to_string(read.synced.rows_missed) +
               " rows its change tracker did not report (a write past its layers): the next " +
               std::to_string(kDistrustedReads) + " plans compare every row (" + std::to_string(missed_writes_) +
               " such changes so far)",
           true);
    }
    // A copy read with nothing known may be older than the costmap the keeper reports on next.
    mirror_behind_ = !changes.known;
    if (settings_.stand_in_for_emptied && !rolling) {  // the stand-in's own question: was it filled?
      mirror_filled_ = emptied_.lastWasFilled();
      if (mirror_filled_) filled_read_ = now;
    }
    return read;
  } catch (...) {
    clear();
    throw;
  }
}

void CostmapSource::clear() {
  mirror_.clear();
  stood_in_.clear();
  mirror_filled_ = false;
  mirror_behind_ = false;
  distrusted_reads_left_ = 0;
  emptied_said_.clear();
}

}  // namespace eaci_service
