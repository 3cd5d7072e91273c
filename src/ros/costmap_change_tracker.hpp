// Where costmap_2d rewrote a costmap's cells since the planner last asked: a costmap_2d layer
// that changes nothing and records the area of every update (issue #31).
//
// Each LayeredCostmap::updateMap resets the master grid inside one rectangle -- the union of
// every layer's bounds -- and has every layer write into it (updateCosts), under the costmap's
// lock; a cleared costmap (resetLayers, ~clear_costmaps) calls every layer's reset(), a resized
// one their matchSize(). So a layer that keeps those rectangles knows every cell that can have
// changed, and the planner, which plans under the same lock, reads only those (CostmapMirror).
// The planner plugins add one to their costmap when they start (track_costmap_changes, on by
// default); without it each plan compares every row of the costmap with the planner's copy.
#pragma once

#include <costmap_2d/layer.h>

#include <mutex>
#include <vector>

#include "costmap_view.hpp"

namespace eaci_ros {

class CostmapChangeTracker : public costmap_2d::Layer {
 public:
  // The rectangles kept at most; more are merged into the one that holds them all.
  static constexpr std::size_t kMaxRects = 32;

  // Enabled from the start (costmap_2d's Layer starts disabled, and updateMap skips a disabled
  // layer: it would never be told of an update).
  CostmapChangeTracker() {
    current_ = true;
    enabled_ = true;
  }

  void updateCosts(costmap_2d::Costmap2D&, int min_i, int min_j, int max_i, int max_j) override;
  void reset() override { markEverything(); }
  void matchSize() override { markEverything(); }

  // What changed since the last take(), and forget it. Call with the costmap's lock held, as
  // updateMap holds it while it writes: the answer then covers every cell read until the lock
  // is released.
  eaci_service::CostmapChanges take();

 private:
  void markEverything();

  std::mutex mutex_;  // a leaf: held for a few vector operations, never while another lock is taken
  bool everything_ = true;  // until the first take(): the planner's copy is made afresh then anyway
  std::vector<eaci_service::BufferRect> rects_;
};

}  // namespace eaci_ros
