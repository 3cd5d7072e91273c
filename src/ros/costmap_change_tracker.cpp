#include "costmap_change_tracker.hpp"

#include <algorithm>
#include <utility>

namespace eaci_ros {

void CostmapChangeTracker::updateCosts(costmap_2d::Costmap2D&, int min_i, int min_j, int max_i, int max_j) {
  if (max_i <= min_i || max_j <= min_j) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (everything_) return;
  try {
    rects_.push_back({min_i, min_j, max_i, max_j});
  } catch (...) {  // no memory for one more: everything may have changed (nothing leaves a layer)
    everything_ = true;
    rects_.clear();
    return;
  }
  if (rects_.size() <= kMaxRects) return;
  eaci_service::BufferRect all = rects_.front();
  for (const eaci_service::BufferRect& r : rects_) {
    all.x0 = std::min(all.x0, r.x0);
    all.y0 = std::min(all.y0, r.y0);
    all.x1 = std::max(all.x1, r.x1);
    all.y1 = std::max(all.y1, r.y1);
  }
  rects_.assign(1, all);
}

void CostmapChangeTracker::markEverything() {
  std::lock_guard<std::mutex> lock(mutex_);
  everything_ = true;
  rects_.clear();
}

eaci_service::CostmapChanges CostmapChangeTracker::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  eaci_service::CostmapChanges changes;
  changes.known = !everything_;
  if (changes.known) changes.rects.swap(rects_);
  rects_.clear();
  everything_ = false;
  return changes;
}

}  // namespace eaci_ros
