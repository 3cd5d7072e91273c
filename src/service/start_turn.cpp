#include "start_turn.hpp"

#include <cmath>
#include <optional>

#include "eaci/path/orientation.hpp"
#include "known_free.hpp"

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
  const double turn = eaci::shortestAngle(start_yaw, std::atan2(d.y(), d.x()));  // + = anticlockwise
  if (std::abs(turn) <= M_PI / 2) return {};
  constexpr double kStep = M_PI / 6;
  const int steps = static_cast<int>(std::ceil(std::abs(turn) / kStep - 1e-9));
  std::vector<Eigen::Vector2d> arc;
  std::optional<eaci::Cell> previous;
  for (int k = 1; k <= steps; ++k) {
    const double angle = start_yaw + turn * k / steps;
    const Eigen::Vector2d p = start + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const std::optional<eaci::Cell> cell = frame.worldToCell(p);
    // Its cell, and the cells on the way from the point before.
    if (!cell || !knownFreeAlong(view, previous.value_or(*cell), *cell)) return {};
    arc.push_back(p);
    previous = cell;
  }
  return arc;
}

}  // namespace eaci_service
