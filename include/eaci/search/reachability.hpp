// Which cells can be reached from a cell under the grid's move rule: a flood by the grid search.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/search/grid_search.hpp"
#include "eaci/search/search_request.hpp"

namespace eaci {

// Flag per cell (index order of the grid): 1 if reachable from `from`. `stop`: ticked once per
// cell flooded; once it says stop the flags are partial (the caller reads stop->stopped()).
inline std::vector<std::uint8_t> reachableFrom(const CostGrid& grid, Cell from, StopPoll* stop = nullptr) {
  GridSearchRequest request;
  request.source = from;
  request.order = SearchOrder::kAnyOrder;
  request.stop = stop;
  const std::vector<double> cost = searchGrid(grid, request).cost;
  std::vector<std::uint8_t> reached(cost.size(), 0);
  for (std::size_t i = 0; i < cost.size(); ++i) reached[i] = std::isfinite(cost[i]) ? 1 : 0;
  return reached;
}

}  // namespace eaci
