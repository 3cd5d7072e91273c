// What a grid search is asked (GridSearchRequest) and what searchGrid answers (GridSearchResult).
//
// A route's cost is the sum of its moves' costs (CostGrid::moveCost); on a binary map (every
// free cell of cost 0) it is the grid distance.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_window.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/search/route_back.hpp"

namespace eaci {

enum class SearchOrder {
  kByCost,    // Dijkstra / A*: cells settle in order of route cost (exact costs)
  kAnyOrder,  // a flood: which cells are reachable, nothing more (cost 0 on each)
};

struct GridSearchRequest {
  Cell source;
  std::optional<Cell> target;  // stop once it is settled; A* steers towards it (octile heuristic)
  std::optional<CellWindow> window;  // default: the whole grid
  bool keep_moves = false;     // remember the move into each cell, for routeTo()
  SearchOrder order = SearchOrder::kByCost;
  bool reverse_costs = false;  // costs of routes *to* the source (see searchGrid)
  // The caller's stop check, ticked once per cell taken off the open list (or flooded); once
  // it says stop the search ends there, with the labels it has (GridSearchResult::stopped).
  StopPoll* stop = nullptr;
};

struct GridSearchResult {
  CellWindow window;
  std::vector<double> cost;            // per window slot: route cost from the source; +infinity = not reached
  std::vector<std::uint8_t> came_dir;  // per window slot (keep_moves): the move into it, kNoMove at the source
  double largest_cost = 0.0;           // over the settled cells
  bool stopped = false;                // ended by the request's stop check: costs are partial

  double at(Cell c) const {
    return window.contains(c) ? cost[window.slot(c)] : std::numeric_limits<double>::infinity();
  }
  bool reached(Cell c) const { return std::isfinite(at(c)); }

  // The cells from the source to `c` (needs keep_moves); empty when `c` was not reached.
  CellPath routeTo(Cell c) const {
    CellPath route;
    if (!reached(c) || came_dir.empty()) return route;
    appendRouteBack(window, c, [this](std::size_t slot) { return came_dir[slot]; }, route);
    std::reverse(route.begin(), route.end());
    return route;
  }
};

}  // namespace eaci
