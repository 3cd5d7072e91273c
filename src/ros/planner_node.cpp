// eaci_planner_node: EACI on a saved map or the /map topic, as a nav_msgs/GetPlan service.
//
//   ~map_file (string)   map_server YAML to load; empty -> subscribe to `map`
//   ~frame_id (string)   frame of a map loaded from ~map_file (default "map"); it is
//                        published latched on `map` for RViz and other nodes
//   every core parameter and the ROS options of planner_options.hpp under ~ (~robot_radius
//   grows the obstacles so that a robot of that radius, planned as a point, keeps clear;
//   ~inflation_radius > 0 and ~cost_scaling_factor add costmap_2d's inflation costs around them,
//   so routes keep off walls as move_base's do);
//   dynamic_reconfigure (cfg/EaciPlanner.cfg) changes them at run time, between two plans. A bad
//   value at start is named on every request, which fails, until it is fixed; a bad value from
//   dynamic_reconfigure is rejected and the values in force stay (planner_configuration.hpp).
// Services: ~make_plan (nav_msgs/GetPlan), ~cancel (std_srvs/Trigger: the plan in progress
// stops at its next iteration and answers with the best route so far). Topics: ~plan
// (nav_msgs/Path), ~pheromone (nav_msgs/OccupancyGrid, with ~visualize_pheromone).
//
// Threads: two spinner threads serve make_plan and the map topic. A plan copies the map (under
// the map's lock, released before it plans) and runs in the planning service
// (src/service/planning_service.hpp), one at a time; a new map never waits for a plan.
// ~cancel has a callback queue and a thread of its own.
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "eaci/io/map_io.hpp"
#include "grid_conversion.hpp"
#include "ros_planner.hpp"

namespace eaci_ros {

class PlannerNode {
 public:
  PlannerNode() : private_nh_("~"), tf_listener_(tf_buffer_) {
    RosPlanner::Setup setup;
    setup.who = "eaci_planner_node";
    setup.latch_plan = true;
    setup.costmap = [this] { return copyMap(); };
    setup.transform = [this](const geometry_msgs::PoseStamped& pose, const std::string& frame,
                             geometry_msgs::PoseStamped& out, std::string& error) {
      try {
        out = tf_buffer_.transform(pose, frame, ros::Duration(0.2));
        return true;
      } catch (const tf2::TransformException& e) {
        error = std::string("cannot be transformed: ") + e.what();
        return false;
      }
    };
    planner_ = std::make_unique<RosPlanner>(private_nh_, std::move(setup));
    std::string map_file;
    private_nh_.param<std::string>("map_file", map_file, "");
    if (!map_file.empty()) {
      std::string frame_id;
      private_nh_.param<std::string>("frame_id", frame_id, "map");
      const nav_msgs::OccupancyGrid loaded = toOccupancyGrid(eaci::loadMap(map_file), frame_id);
      setMap(loaded);
      map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
      map_pub_.publish(loaded);
      ROS_INFO("eaci_planner_node: loaded %s (%u x %u cells, %.3f m)", map_file.c_str(), loaded.info.width,
               loaded.info.height, loaded.info.resolution);
    } else {
      map_sub_ = nh_.subscribe("map", 1, &PlannerNode::onMap, this);
      ROS_INFO("eaci_planner_node: waiting for a map on %s", map_sub_.getTopic().c_str());
    }
  }

 private:
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& map) {
    try {
      setMap(*map);
      ROS_INFO("eaci_planner_node: new map %u x %u cells at %.3f m in frame %s", map->info.width, map->info.height,
               map->info.resolution, map->header.frame_id.c_str());
    } catch (const std::exception& e) {
      ROS_ERROR("eaci_planner_node: cannot use the new map: %s", e.what());
    } catch (...) {
      ROS_ERROR("eaci_planner_node: cannot use the new map: an unknown exception");
    }
  }

  // The map as costmap_2d costs (obstacles 254, unknown 255, with ~inflation_radius the
  // inflation layer's costs), made off the lock and swapped in.
  void setMap(const nav_msgs::OccupancyGrid& map) {
    const RosPlannerOptions options = planner_->options();
    auto costmap = std::make_shared<CostmapSnapshot>();
    costmap->frame_id = map.header.frame_id.empty() ? "map" : map.header.frame_id;
    const bool usable = map.data.size() == static_cast<std::size_t>(map.info.width) * map.info.height &&
                        !map.data.empty() && map.info.resolution > 0;
    if (!usable) {
      ROS_ERROR("eaci_planner_node: the map is empty or malformed; plans will fail until a good one arrives");
      std::lock_guard<std::mutex> lock(map_mutex_);
      map_.reset();
      return;
    }
    const TfMapFrame frame = frameOf(map);
    costmap->frame = frame;
    if (options.inflation_radius > 0) {
      eaci::InflationParameters inflation;
      inflation.inflation_radius = options.inflation_radius;
      inflation.inscribed_radius = options.robot_radius;
      inflation.cost_scaling_factor = options.cost_scaling_factor;
      costmap->cells = inflatedCostsOf(map, options.occupied_threshold, inflation);
      costmap->order = eaci::RowOrder::kTopFirst;
    } else {
      nav_msgs::OccupancyGrid grown = map;
      inflateObstacles(grown, options.robot_radius, options.occupied_threshold);
      costmap->cells.resize(grown.data.size());
      for (std::size_t i = 0; i < grown.data.size(); ++i) {
        const int value = grown.data[i];
        costmap->cells[i] = value < 0 ? kCostmapUnknown : value >= options.occupied_threshold ? kCostmapLethal : kCostmapFree;
      }
      costmap->order = eaci::RowOrder::kBottomFirst;
    }
    std::lock_guard<std::mutex> lock(map_mutex_);
    map_ = std::move(costmap);
  }

  CostmapSnapshot copyMap() const {
    std::shared_ptr<const CostmapSnapshot> map;
    {
      std::lock_guard<std::mutex> lock(map_mutex_);
      map = map_;
    }
    if (!map) throw std::runtime_error("no map yet");
    return *map;  // copied off the lock
  }

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  mutable std::mutex map_mutex_;  // guards map_ only, held for a pointer copy
  std::shared_ptr<const CostmapSnapshot> map_;
  std::unique_ptr<RosPlanner> planner_;
  ros::Subscriber map_sub_;
  ros::Publisher map_pub_;
};

}  // namespace eaci_ros

int main(int argc, char** argv) {
  ros::init(argc, argv, "eaci_planner_node");
  try {
    eaci_ros::PlannerNode node;
    ros::AsyncSpinner spinner(2);  // a second make_plan or a map is served while a plan runs
    spinner.start();
    ros::waitForShutdown();
  } catch (const std::exception& e) {
    ROS_FATAL("eaci_planner_node: %s", e.what());
    return 1;
  } catch (...) {
    ROS_FATAL("eaci_planner_node: an unknown exception");
    return 1;
  }
  return 0;
}
