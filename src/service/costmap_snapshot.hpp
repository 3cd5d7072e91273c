// A copy of a costmap's cells and where it lies: what the ROS adapters hand the planning
// service (planning_service.hpp) after copying it under the costmap's own lock. The service
// owns the copy, so the costmap's lock is never held while it plans.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/costmap_costs.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/map_frame.hpp"

namespace eaci_service {

// costmap_2d's cost values: the core's one copy (eaci/grid/costmap_costs.hpp).
using eaci::kCostmapFree;
using eaci::kCostmapInscribed;
using eaci::kCostmapLethal;
using eaci::kCostmapUnknown;

struct CostmapSnapshot {
  std::vector<std::uint8_t> cells;  // costmap_2d costs, frame.width x frame.height
  eaci::MapFrame frame;
  std::string frame_id;
  // costmap_2d's char map and nav_msgs/OccupancyGrid hold the bottom row first.
  eaci::RowOrder order = eaci::RowOrder::kBottomFirst;

  // Where cell `c` (row 0 = top) is in `cells`.
  std::size_t bufferIndex(eaci::Cell c) const {
    const int buffer_row = order == eaci::RowOrder::kTopFirst ? c.row : frame.height - 1 - c.row;
    return static_cast<std::size_t>(buffer_row) * static_cast<std::size_t>(frame.width) +
           static_cast<std::size_t>(c.col);
  }
};

}  // namespace eaci_service
