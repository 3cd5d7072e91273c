#include "past_goal.hpp"

#include <cmath>

#include "known_free.hpp"

namespace eaci_service {

std::optional<Eigen::Vector2d> pointPastGoal(const eaci::GridView& view, const eaci::MapFrame& frame,
                                             const eaci::CellPath& route, const Eigen::Vector2d& goal,
                                             double distance) {
  if (!(distance > 0) || !std::isfinite(distance) || route.size() < 2) return std::nullopt;
  std::optional<Eigen::Vector2d> from;  // the route's last cell at least two cells before the goal
  for (std::size_t k = route.size() - 1; k-- > 0 && !from;) {
    const Eigen::Vector2d corner = frame.cellToWorld(route[k]);
    if ((goal - corner).norm() >= 2.0 * frame.resolution) from = corner;
  }
  if (!from) return std::nullopt;
  const Eigen::Vector2d past = goal + distance * (goal - *from).normalized();
  const std::optional<eaci::Cell> past_cell = frame.worldToCell(past);
  if (!past_cell) return std::nullopt;
  if (!knownFreeAlong(view, route.back(), *past_cell)) return std::nullopt;
  return past;
}

}  // namespace eaci_service
