#include "eaci_global_planner.hpp"

#include <pluginlib/class_list_macros.hpp>

#include <mutex>
#include <stdexcept>

PLUGINLIB_EXPORT_CLASS(eaci_ros::EaciGlobalPlanner, nav_core::BaseGlobalPlanner)

namespace eaci_ros {

EaciGlobalPlanner::EaciGlobalPlanner(std::string name, costmap_2d::Costmap2DROS* costmap_ros) {
  initialize(std::move(name), costmap_ros);
}

void EaciGlobalPlanner::initialize(std::string name, costmap_2d::Costmap2DROS* costmap_ros) {
  if (planner_) {
    ROS_WARN("EaciGlobalPlanner %s: already initialised", name.c_str());
    return;
  }
  try {
    costmap_ros_ = costmap_ros;
    planner_ = std::make_unique<RosPlanner>(ros::NodeHandle("~/" + name),
                                            RosPlanner::Setup{"EaciGlobalPlanner " + name, false,
                                                              [this] { return copyCostmap(); }, {}, true});
  } catch (const std::exception& e) {
    planner_.reset();
    ROS_ERROR("EaciGlobalPlanner %s: cannot start: %s (every plan will fail)", name.c_str(), e.what());
  } catch (...) {  // move_base must not see an exception from a plugin's initialize (docs/ros.md: "everything")
    planner_.reset();
    ROS_ERROR("EaciGlobalPlanner %s: cannot start: an unknown exception (every plan will fail)", name.c_str());
  }
}

// The costmap's lock is recursive: move_base's planner thread already holds it around makePlan.
CostmapSnapshot EaciGlobalPlanner::copyCostmap() const {
  if (costmap_ros_ == nullptr) throw std::runtime_error("no costmap");
  costmap_2d::Costmap2D* costmap = costmap_ros_->getCostmap();
  CostmapSnapshot copy;
  copy.frame_id = costmap_ros_->getGlobalFrameID();
  std::unique_lock<costmap_2d::Costmap2D::mutex_t> lock(*costmap->getMutex());
  copy.frame.origin = {costmap->getOriginX(), costmap->getOriginY()};
  copy.frame.resolution = costmap->getResolution();
  copy.frame.width = static_cast<int>(costmap->getSizeInCellsX());
  copy.frame.height = static_cast<int>(costmap->getSizeInCellsY());
  const unsigned char* cells = costmap->getCharMap();
  copy.cells.assign(cells, cells + std::size_t{costmap->getSizeInCellsX()} * costmap->getSizeInCellsY());
  return copy;
}

bool EaciGlobalPlanner::makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                                 std::vector<geometry_msgs::PoseStamped>& plan) {
  plan.clear();
  if (!planner_) {
    ROS_ERROR("EaciGlobalPlanner: no plan (%s): makePlan called before a successful initialize()",
              toName(PlanOutcome::kNotInitialised));
    return false;
  }
  return planner_->makePlan(start, goal, -1.0, plan);
}

}  // namespace eaci_ros
