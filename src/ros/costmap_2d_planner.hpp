// What both planner plugins (move_base's nav_core one and Move Base Flex's) share: the planner
// they start on a costmap_2d costmap, and the copy of its cells each plan hands the planning service.
#pragma once

#include <costmap_2d/costmap_2d_ros.h>
#include <ros/ros.h>

#include <cstddef>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "costmap_snapshot.hpp"
#include "ros_planner.hpp"

namespace eaci_ros {

// A copy of the costmap's cells and frame, taken under the costmap's own lock and released
// before it returns. The lock is recursive: move_base's planner thread, and Move Base Flex's
// with planner_lock_costmap, already hold it around makePlan.

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

// Starts the planner of the plugin `kind` ("EaciGlobalPlanner", "EaciCostmapPlanner") named
// `name` into `planner`: parameters, topics and services under ~<name>/, each plan on a copy of
// `costmap_ros`. A second initialize() is said and ignored. When it cannot start, `planner`
// stays null, said at ERROR (every plan then fails as not initialised): nothing leaves it, as
// nothing may leave a plugin's initialize().
inline void startCostmap2DPlanner(std::unique_ptr<RosPlanner>& planner, const std::string& kind,
                                  const std::string& name, costmap_2d::Costmap2DROS* costmap_ros) noexcept {
  try {
    const std::string who = kind + " " + name;
    if (planner) {
      ROS_WARN("%s: already initialised", who.c_str());
      return;
    }
    try {
      planner = std::make_unique<RosPlanner>(
          ros::NodeHandle("~/" + name),
          RosPlanner::Setup{who, false, [costmap_ros] { return copyCostmap2D(costmap_ros); }, {}, true});
    } catch (const std::exception& e) {
      ROS_ERROR("%s: cannot start: %s (every plan will fail)", who.c_str(), e.what());
    }
  } catch (...) {  // not even the sentence
    ROS_ERROR("%s: cannot start: an unknown exception (every plan will fail)", kind.c_str());
  }
}

}  // namespace eaci_ros
