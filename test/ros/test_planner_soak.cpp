// ROS soak: 1,000 ~make_plan calls on a running eaci_planner_node (see planner_soak.test) with
// random free start and goal poses from a fixed seed. Every answer is checked from first
// principles against the map file the node loaded (A* on that map is the reference for "a
// route exists"), and the node's resident memory must not grow from call 200 to call 1,000.
#include <XmlRpc.h>
#include <gtest/gtest.h>
#include <nav_msgs/GetPlan.h>
#include <ros/master.h>
#include <ros/network.h>
#include <ros/ros.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/search/astar.hpp"
#include "route_check.hpp"

namespace {

const char* kNode = "/eaci_planner_node";
const char* kService = "/eaci_planner_node/make_plan";
constexpr int kCalls = 1000;
constexpr int kBaselineCall = 200;
// Allowed growth of the node's resident set from call 200 to call 1,000: a leak of even 2 KiB
// per plan would exceed it, while allocator noise (malloc keeping a freed block or two) stays below.
constexpr double kRssToleranceMiB = 2.0;

// The node's process id through the ROS master (lookupNode) and the node's own XML-RPC
// slave API (getPid), as `rosnode info` does it.
int nodePid(const std::string& node) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  args[1] = node;
  if (!ros::master::execute("lookupNode", args, result, payload, true)) return -1;
  std::string host, path;
  std::uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port)) return -1;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue call_args, reply;
  call_args[0] = ros::this_node::getName();
  if (!client.execute("getPid", call_args, reply) || reply.getType() != XmlRpc::XmlRpcValue::TypeArray ||
      reply.size() != 3 || static_cast<int>(reply[0]) != 1)
    return -1;
  return static_cast<int>(reply[2]);
}

// VmRSS of a process, MiB; negative when it cannot be read.
double residentMiB(int pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) != 0) continue;
    std::istringstream fields(line.substr(6));
    double kib = -1;
    fields >> kib;
    return kib / 1024.0;
  }
  return -1.0;
}

geometry_msgs::PoseStamped pose(const eaci::OccupancyMap& map, eaci::Cell cell, double dx, double dy) {
  const Eigen::Vector2d centre = map.cellToWorld(cell);
  geometry_msgs::PoseStamped p;
  p.header.frame_id = "map";
  p.pose.position.x = centre.x() + dx * map.resolution;
  p.pose.position.y = centre.y() + dy * map.resolution;
  p.pose.orientation.w = 1.0;
  return p;
}

}  // namespace

TEST(PlannerSoak, AThousandRandomPlansAreValidAndTheNodeDoesNotGrow) {
  std::string file;
  ASSERT_TRUE(ros::param::get("~map_file", file));
  const eaci::OccupancyMap map = eaci::loadMap(file);
  // The node plans through unknown cells (allow_unknown); the lab map has none, so free here
  // means free there.
  for (std::uint8_t v : map.cells) ASSERT_NE(v, eaci::kUnknownValue);
  const eaci::CostGrid grid = eaci::CostGrid::fromView(map.view(), false);
  std::vector<eaci::Cell> free_cells;
  for (int r = 0; r < map.height; ++r)
    for (int c = 0; c < map.width; ++c)
      if (grid.isFree({r, c})) free_cells.push_back({r, c});
  ASSERT_FALSE(free_cells.empty());

  ASSERT_TRUE(ros::service::waitForService(kService, ros::Duration(30.0)));
  const int pid = nodePid(kNode);
  ASSERT_GT(pid, 0) << "cannot find the pid of " << kNode << " through the master";
  ASSERT_GT(residentMiB(pid), 0.0);
  ros::ServiceClient client = ros::NodeHandle().serviceClient<nav_msgs::GetPlan>(kService, true);

  std::mt19937_64 rng(20261122);
  std::uniform_int_distribution<std::size_t> pick(0, free_cells.size() - 1);
  std::uniform_real_distribution<double> offset(-0.45, 0.45);  // anywhere inside the cell
  int routes = 0, valid = 0, unreachable = 0;
  double rss_baseline = 0, rss_final = 0;
  const auto begin = std::chrono::steady_clock::now();
  for (int call = 1; call <= kCalls; ++call) {
    const eaci::Cell start = free_cells[pick(rng)], goal = free_cells[pick(rng)];
    nav_msgs::GetPlan srv;
    srv.request.start = pose(map, start, offset(rng), offset(rng));
    srv.request.goal = pose(map, goal, offset(rng), offset(rng));
    ASSERT_TRUE(client.call(srv)) << "call " << call << ": the service call itself failed";
    const bool reachable = eaci::cheapestPath(grid, start, goal).found;
    const auto& poses = srv.response.plan.poses;
    if (!reachable) {
      ++unreachable;
      EXPECT_TRUE(poses.empty()) << "call " << call << ": a route where A* finds none";
    } else {
      EXPECT_FALSE(poses.empty()) << "call " << call << ": no route from (row " << start.row << ", col " << start.col
                                  << ") to (row " << goal.row << ", col " << goal.col << ") although A* finds one";
    }
    if (!poses.empty()) {
      ++routes;
      const std::string defect = eaci_test::routeDefect(map, srv.response.plan, start, goal);
      EXPECT_EQ(defect, "") << "call " << call << ": start (" << srv.request.start.pose.position.x << ", "
                            << srv.request.start.pose.position.y << "), goal (" << srv.request.goal.pose.position.x
                            << ", " << srv.request.goal.pose.position.y << "), " << poses.size() << " poses";
      if (defect.empty()) ++valid;
    }
    if (call == kBaselineCall) rss_baseline = residentMiB(pid);
    if (call == kCalls) rss_final = residentMiB(pid);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  std::printf("planner soak: %d calls, %d routes, %d valid, %d without a route where A* has none either; "
              "node VmRSS %.2f MiB at call %d, %.2f MiB at call %d; %.1f s\n",
              kCalls, routes, valid, unreachable, rss_baseline, kBaselineCall, rss_final, kCalls, seconds);
  RecordProperty("routes", routes);
  RecordProperty("rss_kib_at_200", static_cast<int>(rss_baseline * 1024));
  RecordProperty("rss_kib_at_1000", static_cast<int>(rss_final * 1024));
  EXPECT_EQ(valid, routes);
  ASSERT_GT(rss_baseline, 0.0);
  EXPECT_LE(rss_final - rss_baseline, kRssToleranceMiB)
      << "the node grew from " << rss_baseline << " MiB to " << rss_final << " MiB";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_planner_soak");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
