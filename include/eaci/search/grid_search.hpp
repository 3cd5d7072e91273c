// One search over the grid's moves, behind every exact search of the project: A*
// (cheapestPath), the island leg fields (LegCostField) and reachability
// (reachableFrom). What differs between them is a
// parameter: a target to stop at (and steer towards), a window to stay in, whether to keep
// the moves for the route back, and whether distances matter at all.
//
// Two ways to run it: searchGrid returns a result of its own (a cost per window slot), and
// GridSearchWorkspace (grid_search_workspace.hpp) keeps its buffers for the next search. Both
// run the same loop and find the same costs and moves: cells leave the open list in one total
// order (SearchEntry), whatever the queue.
//
// The loop's speed comes from: an open list that keeps only its lowest priorities in a heap
// (OrderedBucketQueue) and drops entries gone stale before they reach it, integer priority
// compares, the allowed moves of a cell as one bit mask (no bounds checks away from the
// border), and, with a workspace, no clearing of whole-map arrays.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "eaci/grid/cell_window.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/search/bucket_queue.hpp"
#include "eaci/search/neighbourhood.hpp"
#include "eaci/search/octile.hpp"
#include "eaci/search/route_back.hpp"
#include "eaci/search/search_request.hpp"

namespace eaci {
namespace detail {

// The loop of every search, on labels kept by `Labels`: cost(slot) (+infinity when not
// reached) and label(slot, cost, move). Returns the largest settled cost; `stopped` says
// whether the request's stop check ended it.
template <class Labels>
double runGridSearch(const CostGrid& grid, const GridSearchRequest& request, const CellWindow& window, Labels& labels,
                     OrderedBucketQueue& open, std::vector<std::uint32_t>& frontier, bool& stopped) {
  stopped = false;
  if (!grid.isFree(request.source) || !window.contains(request.source)) return 0.0;
  StopPoll never;
  StopPoll& poll = request.stop != nullptr ? *request.stop : never;
  const SearchNeighbourhood around(grid, window);
  const auto source = static_cast<std::uint32_t>(window.slot(request.source));
  labels.label(source, 0.0, kNoMove);

  if (request.order == SearchOrder::kAnyOrder) {  // a flood: depth first, each cell once
    frontier.clear();
    frontier.push_back(source);
    while (!frontier.empty()) {
      if (poll.tick()) {
        stopped = true;
        return 0.0;
      }
      const std::uint32_t slot = frontier.back();
      frontier.pop_back();
      const Cell here = window.cellAt(slot);
      for (unsigned moves = around.movesFrom(here); moves != 0; moves &= moves - 1) {
        const std::uint32_t j = around.slotTowards(slot, lowestBit(moves));
        if (labels.cost(j) == 0.0) continue;
        labels.label(j, 0.0, kNoMove);
        frontier.push_back(j);
      }
    }
    return 0.0;
  }

  const bool steer = request.target.has_value();
  const Cell target = request.target.value_or(Cell{});
  constexpr std::uint32_t kNoTarget = std::numeric_limits<std::uint32_t>::max();
  const std::uint32_t target_slot =
      steer && window.contains(target) ? static_cast<std::uint32_t>(window.slot(target)) : kNoTarget;
  double largest_cost = 0.0;
  open.clear();
  open.push({steer ? octileDistance(request.source, target) : 0.0, 0.0, source});
  const auto stale = [&labels](const SearchEntry& e) { return e.cost > labels.cost(e.slot); };
  SearchEntry top;
  while (open.pop(top, stale)) {
    if (poll.tick()) {  // counts stale entries too: they cost a pop
      stopped = true;
      break;
    }
    if (stale(top)) continue;  // settled before, by a cheaper way
    largest_cost = std::max(largest_cost, top.cost);
    if (top.slot == target_slot) break;
    relaxMoves(grid, around, top.slot, window.cellAt(top.slot), top.cost, request.reverse_costs, labels,
               [&](std::uint32_t j, Cell next, double g) { open.push({steer ? g + octileDistance(next, target) : g, g, j}); });
  }
  return largest_cost;
}

// Labels in a result's own arrays (filled with +infinity first).
struct ResultLabels {
  double* costs;
  std::uint8_t* moves;  // null: moves not kept
  double cost(std::uint32_t slot) const { return costs[slot]; }
  static double kept(double c) { return c; }
  void label(std::uint32_t slot, double c, std::uint8_t move) {
    costs[slot] = c;
    if (moves != nullptr) moves[slot] = move;
  }
};
}  // namespace detail

// The open list and flood stack of searchGrid, kept by a caller that runs many small searches
// (one per island leg), so that each costs no allocation of its own.
struct GridSearchScratch {
  detail::OrderedBucketQueue open;
  std::vector<std::uint32_t> frontier;
};

// The search itself. A blocked or off-window source reaches nothing. A move costs by the cell
// it enters, so costs from the source are not costs to it on a cost map (they are on a binary
// map): a field that must hold costs *to* its source searches the reversed moves
// (`reverse_costs`), which charge the cell a move leaves instead.
inline GridSearchResult searchGrid(const CostGrid& grid, const GridSearchRequest& request, GridSearchScratch& scratch) {
  GridSearchResult result;
  result.window = request.window.value_or(CellWindow::whole(grid));
  result.cost.assign(result.window.size(), std::numeric_limits<double>::infinity());
  if (request.keep_moves) result.came_dir.assign(result.window.size(), kNoMove);
  detail::ResultLabels labels{result.cost.data(), request.keep_moves ? result.came_dir.data() : nullptr};
  result.largest_cost =
      detail::runGridSearch(grid, request, result.window, labels, scratch.open, scratch.frontier, result.stopped);
  return result;
}

inline GridSearchResult searchGrid(const CostGrid& grid, const GridSearchRequest& request) {
  GridSearchScratch scratch;
  return searchGrid(grid, request, scratch);
}

}  // namespace eaci
