// What both planner plugins (move_base's nav_core one and Move Base Flex's) share: the planner
// they start on a costmap_2d costmap, the costmap each plan hands the planning service (its own
// cells under its lock, with what changed since the last plan), and the copy for ~make_plan.
#pragma once

#include <costmap_2d/costmap_2d_ros.h>
#include <ros/ros.h>

#include <cstddef>
#include <memory>
#include <mutex>
#include <boost/make_shared.hpp>
#include <stdexcept>
#include <string>

#include "costmap_change_tracker.hpp"
#include "costmap_snapshot.hpp"
#include "ros_planner.hpp"

namespace eaci_ros {

// The costmap's cells and frame as they are (call with its lock held): valid while it is held.
inline eaci_service::CostmapView costmap2DView(const costmap_2d::Costmap2DROS& costmap_ros) {
  const costmap_2d::Costmap2D& costmap = *costmap_ros.getCostmap();
  eaci_service::CostmapView view;
  view.frame_id = costmap_ros.getGlobalFrameID();
  view.frame.origin = {costmap.getOriginX(), costmap.getOriginY()};
  view.frame.resolution = costmap.getResolution();
  view.frame.width = static_cast<int>(costmap.getSizeInCellsX());
  view.frame.height = static_cast<int>(costmap.getSizeInCellsY());
  view.cells = costmap.getCharMap();
  view.order = eaci::RowOrder::kBottomFirst;  // costmap_2d keeps the row at the origin first
  return view;
}

// A copy of the costmap's cells and frame, taken under the costmap's own lock and released
// before it returns. The lock is recursive: move_base's planner thread, and Move Base Flex's
// with planner_lock_costmap, already hold it around makePlan.
inline eaci_service::CostmapSnapshot copyCostmap2D(costmap_2d::Costmap2DROS* costmap_ros) {
  if (costmap_ros == nullptr) throw std::runtime_error("no costmap");
  std::unique_lock<costmap_2d::Costmap2D::mutex_t> lock(*costmap_ros->getCostmap()->getMutex());
  const eaci_service::CostmapView view = costmap2DView(*costmap_ros);
  eaci_service::CostmapSnapshot copy;
  copy.frame_id = view.frame_id;
  copy.frame = view.frame;
  copy.order = view.order;
  copy.cells.assign(view.cells, view.cells + view.cellCount());
  return copy;
}

// Plans on the costmap's own cells: takes its (recursive) lock, which move_base's planner thread
// and Move Base Flex's with planner_lock_costmap already hold around makePlan, for the plan,
// and tells the planner what `tracker` saw change (null: nothing known, every row compared).
inline eaci_service::PlanReply planOnCostmap2D(costmap_2d::Costmap2DROS* costmap_ros, CostmapChangeTracker* tracker,
                                               const RosPlanner::CostmapPlan& plan) {
  if (costmap_ros == nullptr) throw std::runtime_error("no costmap");
  std::unique_lock<costmap_2d::Costmap2D::mutex_t> lock(*costmap_ros->getCostmap()->getMutex());
  return plan(costmap2DView(*costmap_ros),
              tracker != nullptr ? tracker->take() : eaci_service::CostmapChanges::unknown());
}

// A CostmapChangeTracker added to `costmap_ros`'s layers (under its lock), or null with the
// reason said when it cannot be (plans then compare every row).
inline boost::shared_ptr<CostmapChangeTracker> addChangeTracker(const std::string& who, const std::string& name,
                                                                 costmap_2d::Costmap2DROS* costmap_ros) {
  try {
    costmap_2d::LayeredCostmap* layers = costmap_ros->getLayeredCostmap();
    auto tracker = boost::make_shared<CostmapChangeTracker>();
    std::unique_lock<costmap_2d::Costmap2D::mutex_t> lock(*costmap_ros->getCostmap()->getMutex());
    tracker->initialize(layers, name + "_change_tracker", nullptr);
    layers->addPlugin(tracker);
    return tracker;
  } catch (const std::exception& e) {
    ROS_WARN("%s: cannot track the costmap's changes (%s): each plan compares every row of it", who.c_str(), e.what());
  }
  return nullptr;
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
      if (costmap_ros == nullptr) throw std::runtime_error("no costmap");
      const ros::NodeHandle private_nh("~/" + name);
      // ~track_costmap_changes: a layer records where costmap_2d rewrites the costmap, so a plan
      // reads only that (CostmapChangeTracker); false: every plan compares every row.
      boost::shared_ptr<CostmapChangeTracker> tracker;
      if (private_nh.param("track_costmap_changes", true)) tracker = addChangeTracker(who, name, costmap_ros);
      RosPlanner::Setup setup{who, false, [costmap_ros] { return copyCostmap2D(costmap_ros); },
                              [costmap_ros, tracker](const RosPlanner::CostmapPlan& plan) {
                                return planOnCostmap2D(costmap_ros, tracker.get(), plan);
                              },
                              {}, true};
      planner = std::make_unique<RosPlanner>(private_nh, std::move(setup));
    } catch (const std::exception& e) {
      ROS_ERROR("%s: cannot start: %s (every plan will fail)", who.c_str(), e.what());
    }
  } catch (...) {  // not even the sentence
    ROS_ERROR("%s: cannot start: an unknown exception (every plan will fail)", kind.c_str());
  }
}

}  // namespace eaci_ros
