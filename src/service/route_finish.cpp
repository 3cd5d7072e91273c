#include "route_finish.hpp"

#include <algorithm>
#include <cmath>

#include "eaci/grid/cell_point.hpp"
#include "route_defect.hpp"

namespace eaci_service {

std::vector<Eigen::Vector2d> posesAlong(const eaci::CellPath& corners, const eaci::MapFrame& frame,
                                        const Eigen::Vector2d& start, const Eigen::Vector2d& goal) {
  std::vector<Eigen::Vector2d> poses;
  if (corners.empty()) return poses;
  constexpr double kSamePlace = 1e-9;  // m: only a centre exactly there (else the next pose could lie over a cell away)
  poses.push_back(start);
  const Eigen::Vector2d first = frame.cellToWorld(corners.front());
  if ((first - start).norm() > kSamePlace) poses.push_back(first);
  for (std::size_t k = 1; k < corners.size(); ++k) {
    const eaci::CellPoint a = eaci::cellPoint(corners[k - 1]), b = eaci::cellPoint(corners[k]);
    // Pieces of at most one cell; the 1e-9 keeps a whole number of cells from gaining a piece.
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() - 1e-9)));
    for (int i = 1; i <= pieces; ++i) poses.push_back(frame.pointToWorld(a + (b - a) * (static_cast<double>(i) / pieces)));
  }
  if ((poses.back() - goal).norm() > kSamePlace) poses.push_back(goal);
  else poses.back() = goal;
  if (poses.size() == 1) poses.push_back(goal);  // start and goal in one place: two poses, as navfn's
  return poses;
}

std::string posesDefect(const eaci::GridView& view, const eaci::MapFrame& frame,
                        const std::vector<Eigen::Vector2d>& poses, bool allow_corner_cutting) {
  eaci::CellPolyline points;
  points.reserve(poses.size());
  for (const Eigen::Vector2d& p : poses) points.push_back(frame.worldToPoint(p));
  return polylineDefect(view, points, allow_corner_cutting);
}

FinishedRoute finishRoute(const eaci::GridView& view, const eaci::MapFrame& frame, const eaci::CellPath& smoothed,
                          const eaci::CellPath& grid, const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                          bool allow_corner_cutting, const std::function<void(std::vector<Eigen::Vector2d>&)>& inject) {
  FinishedRoute finished;
  finished.poses = posesAlong(smoothed, frame, start, goal);
  if (inject) inject(finished.poses);
  finished.smoothed_defect = posesDefect(view, frame, finished.poses, allow_corner_cutting);
  if (finished.smoothed_defect.empty()) return finished;
  finished.grid_route = true;
  finished.poses = posesAlong(grid, frame, start, goal);
  const std::string grid_defect = posesDefect(view, frame, finished.poses, allow_corner_cutting);
  if (grid_defect.empty()) return finished;
  finished.poses.clear();
  finished.defect = "the smoothed route's poses: " + finished.smoothed_defect + "; the grid route's: " + grid_defect;
  return finished;
}

}  // namespace eaci_service
