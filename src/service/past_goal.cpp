#include "past_goal.hpp"

#include <cmath>

namespace eaci_service {

std::optional<Eigen::Vector2d> pointPastGoal(const eaci::GridView& view, const eaci::MapFrame& frame,
                                             const eaci::CellPath& route, const Eigen::Vector2d& goal,
                                             double distance) {
  if (!(distance > 0) || !std::isfinite(distance) || route.size() < 2) return std::nullopt;
  std::optional<Eigen::Vector2d> from;  // the route's last cell at least two cells before the goal
  for (std::size_t k = route.size() - 1; k-- > 0 && !from;)
    if ((goal - frame.cellToWorld(route[k])).norm() >= 2.0 * frame.resolution) from = frame.cellToWorld(route[k]);
  if (!from) return std::nullopt;
  const Eigen::Vector2d direction = (goal - *from).normalized();
  const Eigen::Vector2d past = goal + distance * direction;
  const int samples = static_cast<int>(std::ceil(2.0 * distance / frame.resolution));  // every half cell
  for (int s = 1; s <= samples; ++s) {
    const std::optional<eaci::Cell> cell = frame.worldToCell(goal + (distance * s / samples) * direction);
    if (!cell || !view.isFree(*cell) || view.value(*cell) == view.interpretation().unknown_value) return std::nullopt;
  }
  return past;
}

}  // namespace eaci_service
