#include "start_cell.hpp"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace eaci_service {

StartCellCheck openStartCell(const CostmapSnapshot& costmap, const eaci::CellInterpretation& interpretation,
                             eaci::Cell start, const std::function<bool()>& should_stop) {
  StartCellCheck check;
  const int width = costmap.frame.width, height = costmap.frame.height;
  const auto contains = [&](eaci::Cell c) { return c.row >= 0 && c.col >= 0 && c.row < height && c.col < width; };
  if (!contains(start)) {
    check.outcome = PlanOutcome::kStartOffMap;
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
    check.outcome = PlanOutcome::kStartBlocked;
    check.error = "the start is in a lethal obstacle (costmap cost 254): the robot's centre is inside an obstacle";
    return check;
  }
  // Dijkstra from the start over the band's cells (obstacles to the planner, but not lethal),
  // each entered at its cost + 1, until the first free cell is taken. Labels only for the cells
  // it reaches: its work and memory follow the band around the robot, not the map.
  using Index = std::uint32_t;
  const auto index = [&](eaci::Cell c) { return static_cast<Index>(static_cast<std::size_t>(c.row) * width + c.col); };
  const auto cellOf = [&](Index i) { return eaci::Cell{static_cast<int>(i / width), static_cast<int>(i % width)}; };
  struct Label {
    double cost;
    Index parent;
  };
  constexpr Index kNoParent = std::numeric_limits<Index>::max();
  std::unordered_map<Index, Label> labels;
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  labels[index(start)] = {0.0, kNoParent};
  open.push({0.0, index(start)});
  const int drow[4] = {-1, 1, 0, 0}, dcol[4] = {0, 0, -1, 1};
  std::size_t popped = 0;
  Index exit = kNoParent;
  while (!open.empty()) {
    const auto [here_cost, here] = open.top();
    open.pop();
    if (here_cost > labels[here].cost) continue;
    if (should_stop && ++popped % 4096 == 0 && should_stop()) {
      check.stopped = true;
      check.error = "stopped while looking for the way out of the inflated band around the start";
      return check;
    }
    const eaci::Cell cell = cellOf(here);
    if (!interpretation.isObstacle(value(cell))) {
      exit = here;
      break;
    }
    for (int d = 0; d < 4; ++d) {
      const eaci::Cell next{cell.row + drow[d], cell.col + dcol[d]};
      if (!contains(next) || value(next) == kCostmapLethal) continue;
      const double next_cost = here_cost + 1.0 + value(next);
      const auto [label, added] = labels.try_emplace(index(next), Label{next_cost, here});
      if (!added && next_cost >= label->second.cost) continue;
      label->second = {next_cost, here};
      open.push({next_cost, index(next)});
    }
  }
  if (exit == kNoParent) {
    check.outcome = PlanOutcome::kStartBlocked;
    check.error = "the start is in the inflated band of an obstacle and no free cell can be reached from it";
    return check;
  }
  // lethal_cost - 1: the costliest cost a planner still crosses.
  check.opened_cost = static_cast<std::uint8_t>(std::max(0, int(interpretation.lethal_cost) - 1));
  for (Index i = labels[exit].parent; i != kNoParent; i = labels[i].parent) check.opened.push_back(cellOf(i));
  check.cells_opened = static_cast<int>(check.opened.size());
  check.ok = true;
  return check;
}

}  // namespace eaci_service
