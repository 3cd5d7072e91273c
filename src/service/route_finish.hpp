// The stage that finishes a plan: the poses that go out to the robot, made from the route and
// checked, every segment between two consecutive poses, against the costmap the plan was made
// on (route_defect.hpp: the segment walk the smoother uses too). What is checked is exactly what
// the adapters send: they only add headings (eaci::orientPoints) and the message's header.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/map_frame.hpp"

namespace eaci_service {

// The positions of the poses along the polyline of cell centres `corners` (start cell first,
// target cell last), in the frame's world coordinates: `start` (the robot's position, in the
// first cell), the first cell's centre, points along every segment at most one cell apart (as
// navfn's and global_planner's poses), the last cell's centre, then `goal` (in the last cell).
// A centre where `start` or `goal` is (within 1e-9 m) is left out. Empty for no corners.
std::vector<Eigen::Vector2d> posesAlong(const eaci::CellPath& corners, const eaci::MapFrame& frame,
                                        const Eigen::Vector2d& start, const Eigen::Vector2d& goal);

// "" when the straight segment between every two consecutive `poses` (world coordinates in
// `frame`) passes only cells `view` lets a robot cross (polylineDefect), else what is wrong.
std::string posesDefect(const eaci::GridView& view, const eaci::MapFrame& frame,
                        const std::vector<Eigen::Vector2d>& poses, bool allow_corner_cutting);

struct FinishedRoute {
  std::vector<Eigen::Vector2d> poses;  // what goes out; empty when neither route passed the check
  bool grid_route = false;             // the smoothed route's poses failed the check: the grid route's went
  std::string smoothed_defect;         // why they failed ("" when they passed)
  std::string defect;                  // why nothing passed ("" when `poses` is filled)
};

// The poses of `smoothed` when every segment between them passes the check; else those of
// `grid` (the planner's 8-connected route) when they do; else none, with both reasons.
// `inject` (tests only) changes the smoothed route's poses before their check.
FinishedRoute finishRoute(const eaci::GridView& view, const eaci::MapFrame& frame, const eaci::CellPath& smoothed,
                          const eaci::CellPath& grid, const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                          bool allow_corner_cutting,
                          const std::function<void(std::vector<Eigen::Vector2d>&)>& inject = {});

}  // namespace eaci_service
