// A copy of a costmap_2d costmap's cells and frame, taken under the costmap's own lock and
// released before it returns: what both planner plugins (move_base's and Move Base Flex's) hand
// to the planning service. The lock is recursive: move_base's planner thread, and Move Base
// Flex's with planner_lock_costmap, already hold it around makePlan.
#pragma once

#include <costmap_2d/costmap_2d_ros.h>

#include <cstddef>
#include <mutex>
#include <stdexcept>

#include "costmap_snapshot.hpp"

namespace eaci_ros {

inline eaci_service::CostmapSnapshot copyCostmap2D(costmap_2d::Costmap2DROS* costmap_ros) {
  if (costmap_ros == nullptr) throw std::runtime_error("no costmap");
  costmap_2d::Costmap2D* costmap = costmap_ros->getCostmap();
  eaci_service::CostmapSnapshot copy;
  copy.frame_id = costmap_ros->getGlobalFrameID();
  std::unique_lock<costmap_2d::Costmap2D::mutex_t> lock(*costmap->getMutex());
  copy.frame.origin = {costmap->getOriginX(), costmap->getOriginY()};
  copy.frame.resolution = costmap->getResolution();
  copy.frame.width = static_cast<int>(costmap->getSizeInCellsX());
  copy.frame.height = static_cast<int>(costmap->getSizeInCellsY());
  const unsigned char* cells = costmap->getCharMap();
  copy.cells.assign(cells, cells + std::size_t{costmap->getSizeInCellsX()} * costmap->getSizeInCellsY());
  return copy;
}

}  // namespace eaci_ros
