// A goal tolerance by reachability, as navfn's: the cell nearest to the goal, within the
// tolerance, that a route from the start can reach.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/nearest_free.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/search/reachability.hpp"

namespace eaci {

// The cell of `grid` nearest to `goal` (Euclidean distance between centres, in cells) within
// `radius_cells` that can be reached from `start` under the grid's move rule: `goal` itself if
// reachable; of equally near cells the first in row-major order; none if no cell within the
// radius can be reached (a free cell behind a wall never wins over a reachable one further
// away). navfn's makePlan does the same from its potential field: of the cells in the
// tolerance square, the one nearest the goal whose potential is finite.
//
// The work is one flood of the cells reachable from `start` (reachableFrom), then the ring
// search of nearestCellWhere: call it when the goal is known to be blocked or unreachable, not
// on every plan. `should_stop` (a std::function<bool()>, a StopCheck, any callable, or empty)
// is asked by both every StopPoll::kWorkBetweenChecks cells; once it says stop the answer is
// none (nullopt): the caller tells that apart from "none within the radius" by its own check.
template <class Check = std::function<bool()>>
std::optional<Cell> nearestReachableCell(const CostGrid& grid, Cell start, Cell goal, double radius_cells,
                                         const Check& should_stop = Check{}) {
  if (!grid.isFree(start) || !(radius_cells >= 0)) return std::nullopt;
  StopPoll poll(should_stop);
  const std::vector<std::uint8_t> reached = reachableFrom(grid, start, &poll);
  if (poll.stopped()) return std::nullopt;
  return nearestCellWhere(grid.width(), grid.height(), goal, radius_cells,
                          [&](Cell c) { return reached[grid.index(c)] != 0; }, should_stop);
}

}  // namespace eaci
