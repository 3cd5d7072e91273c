#include "start_cell.hpp"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace eaci_ros {

StartCellCheck openStartCell(CostmapSnapshot& costmap, const eaci::CellInterpretation& interpretation,
                             eaci::Cell start, const std::function<bool()>& should_stop) {
  StartCellCheck check;
  const int width = costmap.frame.width, height = costmap.frame.height;
  const auto contains = [&](eaci::Cell c) { return c.row >= 0 && c.col >= 0 && c.row < height && c.col < width; };
  if (!contains(start)) {
    check.error = "the start cell is off the costmap";
    return check;
  }
  const auto value = [&](eaci::Cell c) { return costmap.cells[costmap.bufferIndex(c)]; };
  check.start_cost = value(start);
  if (!interpretation.isObstacle(check.start_cost)) {
    check.ok = true;
    return check;
  }
  if (check.start_cost == kCostmapLethal) {
    check.error = "the start is in a lethal obstacle (costmap cost 254): the robot's centre is inside an obstacle";
    return check;
  }
  // Dijkstra from the start over the band's cells (obstacles to the planner, but not lethal),
  // each entered at its cost + 1, until the first free cell is taken.
  const auto index = [&](eaci::Cell c) { return static_cast<std::size_t>(c.row) * width + c.col; };
  std::vector<double> cost(static_cast<std::size_t>(width) * height, std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> parent(cost.size(), std::numeric_limits<std::uint32_t>::max());
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost[index(start)] = 0.0;
  open.push({0.0, static_cast<std::uint32_t>(index(start))});
  const int drow[4] = {-1, 1, 0, 0}, dcol[4] = {0, 0, -1, 1};
  std::size_t popped = 0;
  std::uint32_t exit = std::numeric_limits<std::uint32_t>::max();
  while (!open.empty()) {
    const auto [here_cost, here] = open.top();
    open.pop();
    if (here_cost > cost[here]) continue;
    if (should_stop && ++popped % 4096 == 0 && should_stop()) {
      check.error = "stopped while looking for the way out of the inflated band around the start";
      return check;
    }
    const eaci::Cell cell{static_cast<int>(here / width), static_cast<int>(here % width)};
    if (!interpretation.isObstacle(value(cell))) {
      exit = here;
      break;
    }
    for (int d = 0; d < 4; ++d) {
      const eaci::Cell next{cell.row + drow[d], cell.col + dcol[d]};
      if (!contains(next) || value(next) == kCostmapLethal) continue;
      const double next_cost = here_cost + 1.0 + value(next);
      const std::size_t j = index(next);
      if (next_cost < cost[j]) {
        cost[j] = next_cost;
        parent[j] = here;
        open.push({next_cost, static_cast<std::uint32_t>(j)});
      }
    }
  }
  if (exit == std::numeric_limits<std::uint32_t>::max()) {
    check.error = "the start is in the inflated band of an obstacle and no free cell can be reached from it";
    return check;
  }
  // lethal_cost - 1: the costliest cost a planner still crosses.
  const std::uint8_t passable = static_cast<std::uint8_t>(std::max(0, int(interpretation.lethal_cost) - 1));
  for (std::uint32_t i = parent[exit]; i != std::numeric_limits<std::uint32_t>::max(); i = parent[i]) {
    costmap.cells[costmap.bufferIndex({static_cast<int>(i / width), static_cast<int>(i % width)})] = passable;
    ++check.cells_opened;
  }
  check.ok = true;
  return check;
}

}  // namespace eaci_ros
