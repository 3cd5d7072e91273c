#include "start_turn.hpp"

#include <cmath>
#include <optional>

namespace eaci_service {

std::vector<Eigen::Vector2d> startTurnArc(const eaci::GridView& view, const eaci::MapFrame& frame,
                                          const eaci::CellPath& route, const Eigen::Vector2d& start,
                                          double start_yaw, double radius) {
  if (!(radius > 0) || !std::isfinite(radius) || !std::isfinite(start_yaw)) return {};
  std::optional<Eigen::Vector2d> ahead;  // the route's first point at least 2 x radius from the start
  for (const eaci::Cell& c : route) {
    const Eigen::Vector2d p = frame.cellToWorld(c);
    if ((p - start).norm() >= 2.0 * radius) {
      ahead = p;
      break;
    }
  }
  if (!ahead) return {};
  const Eigen::Vector2d d = *ahead - start;
  const double turn = std::remainder(std::atan2(d.y(), d.x()) - start_yaw, 2.0 * M_PI);  // (-pi, pi], + = anticlockwise
  if (std::abs(turn) <= M_PI / 2) return {};
  constexpr double kStep = M_PI / 6;
  const int steps = static_cast<int>(std::ceil(std::abs(turn) / kStep - 1e-9));
  std::vector<Eigen::Vector2d> arc;
  for (int k = 1; k <= steps; ++k) {
    const double angle = start_yaw + turn * k / steps;
    const Eigen::Vector2d p = start + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const std::optional<eaci::Cell> cell = frame.worldToCell(p);
    if (!cell || !view.isFree(*cell) || view.value(*cell) == view.interpretation().unknown_value) return {};
    arc.push_back(p);
  }
  return arc;
}

}  // namespace eaci_service
