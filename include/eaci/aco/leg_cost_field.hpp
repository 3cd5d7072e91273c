// Exact cost of the cheapest route to the island an ant is heading for (the grid distance on
// a binary map), the leg heuristic of the geodesic island strategy (beyond the paper; the paper
// uses the straight-line distance).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "eaci/aco/islands.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/search/grid_search.hpp"

namespace eaci {

// Route cost to one island, computed in a window around its leg (the leg's cells plus a
// margin). Cells the window does not reach read as the Euclidean distance (never more than the
// cost), raised to at least one more than the largest cost inside the window, so they never
// look better.
class LegCostField {
 public:
  // The window reaches this many cells beyond the leg, or half the leg's length if more. With
  // islands 2 cells apart one cell is enough: an ant further off than that heads back anyway
  // (the region's other cells read as costlier), and a field of one island costs ~20 cells
  // instead of ~120 with 4 (512 maze: EACI/A* time 4.3x -> 2.9x at 512-1024 cells, same routes).
  static constexpr int kMinWindowMargin = 1;

  LegCostField() = default;

  // `leg` is the part of the cheapest route from the previous island to `target`.
  // `scratch`: the search's open list, shared by the fields of one plan (null: its own).
  // `stop`: ticked once per cell of the search (a stopped field is partial; its caller drops it).
  LegCostField(const CostGrid& grid, const CellPath& leg, Cell target, GridSearchScratch* scratch = nullptr,
                   StopPoll* stop = nullptr)
      : target_(target) {
    CellPath extent = leg;
    extent.push_back(target);
    GridSearchRequest request;
    request.source = target;
    request.reverse_costs = true;  // costs of routes to the island
    request.stop = stop;
    request.window = CellWindow::around(grid, extent, std::max(kMinWindowMargin, static_cast<int>(leg.size()) / 2));
    field_ = scratch != nullptr ? searchGrid(grid, request, *scratch) : searchGrid(grid, request);
    outside_ = field_.largest_cost + 1.0;
  }

  // Cost of the cheapest route from `c` to the island (cells on a binary map).
  double at(Cell c) const {
    const double d = field_.at(c);
    return std::isfinite(d) ? d : std::max(euclidean(c, target_), outside_);
  }

 private:
  Cell target_{};
  GridSearchResult field_;
  double outside_ = 0.0;
};

// One field per island after S (index = the island's index), read by the ant walk. Stopped by
// `stop` (every few thousand cells of their searches): the fields made so far, the rest empty;
// the caller reads stop->stopped() and drops them.
inline std::vector<LegCostField> legCostFields(const CostGrid& grid, const CellPath& shortest_route,
                                                       const std::vector<Cell>& islands, StopPoll* stop = nullptr) {
  std::vector<LegCostField> fields(islands.size());
  GridSearchScratch scratch;
  std::size_t from = 0;
  for (std::size_t z = 1; z < islands.size(); ++z) {
    std::size_t to = from;
    while (to < shortest_route.size() && !(shortest_route[to] == islands[z])) ++to;
    const CellPath leg(shortest_route.begin() + static_cast<std::ptrdiff_t>(from),
                       shortest_route.begin() + static_cast<std::ptrdiff_t>(std::min(to + 1, shortest_route.size())));
    fields[z] = LegCostField(grid, leg, islands[z], &scratch, stop);
    if (stop != nullptr && stop->stopped()) break;
    from = to;
  }
  return fields;
}

}  // namespace eaci
