// The exact reference of the combined objective (issue #30): a cheapest route when a route costs
// its moves (CostGrid::moveCost, as A* prices them) plus turn_cost x its heading change in
// radians (combinedRouteCost, grid/cost_grid.hpp). A cell search cannot see a heading, so this
// one searches (cell, incoming direction) states, 8 per cell: A* from the start's moves to the
// first state of the goal cell that settles.
//
// Without end headings the start has no heading (its first move turns nothing) and the goal may
// be entered in any direction. A move from state (c, h) in direction d costs moveCost +
// turn_cost x turnSteps(h, d) x pi/4 and reaches state (c + d, d). With end headings
// (grid/end_headings.hpp) the first move also pays turn_cost x its turn from the start heading,
// and a goal state (goal, h) settled at g offers the route g + turn_cost x the turn from h onto
// the goal heading: that total goes on the open list as a final step, and the first final step
// taken off it is the cheapest (its priority is its cost, and every state with a lower priority
// has been settled before it).
//
// The bound: octile(c, goal) (no move costs less than its length) plus turn_cost x pi/4 x
// turnStepsAtLeast(h, goal - c): a route that starts with heading h and never turns by more
// than k x 45 degrees in total only uses directions within k x 45 degrees of h, so its moves
// add up to a vector within k x 45 degrees of h; the goal's offset needs k at least the angle
// from h to it, rounded up to 45 degrees. Both parts are consistent (a move changes the octile
// distance by at most its length, and the angle to the goal by at most the turn it makes), so
// a state's label is final when it settles. A state is dropped when another heading at its cell
// is cheaper by more than the turn between them (HeadingLabels::dominated); that stays exact with
// a goal heading, since the turn onto it obeys the same triangle inequality.
//
// Memory (docs/benchmarks.md 10.10): 8 bytes per cell the search reaches, and cost labels only
// for the cells with open states (HeadingLabels, search/heading_labels.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_window.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/end_headings.hpp"
#include "eaci/grid/moves.hpp"
#include "eaci/parallel/stop_poll.hpp"
#include "eaci/search/astar.hpp"
#include "eaci/search/bucket_queue.hpp"
#include "eaci/search/neighbourhood.hpp"
#include "eaci/search/octile.hpp"
#include "eaci/search/heading_labels.hpp"

namespace eaci {

// The most cells the heading search takes: 8 states per cell are numbered with 32-bit
// numbers on the open list (cell x 8 + heading).
constexpr std::size_t kMaxHeadingSearchCells = (std::size_t{1} << 29) - 1;

// A cheapest route under the combined objective. `cost`, `length` and `path` as in
// CheapestPath (cost = the move costs alone, routeCost).
struct TurningPath : CheapestPath {
  double combined_cost = std::numeric_limits<double>::infinity();  // combinedRouteCost of the path
  long long turn_steps = 0;  // the path's heading change in 45-degree steps (routeTurnSteps)
};

// The search, with its open list kept for the next one (its labels are each search's own,
// freed at its end). One search at a time.
class HeadingSearch {
 public:
  // What the last search did: states settled (taken off the open list live), and the most
  // cells with open states at once (HeadingLabels' blocks).
  struct Stats {
    std::size_t settled = 0;
    std::size_t open_blocks = 0;
  };

  // A cheapest route from start to goal under the combined objective with `turn_cost` (>= 0,
  // finite), with the turns at the route's ends priced as `ends` says. found = false when
  // either cell is off the map or blocked, or the goal cannot be reached; `stop` is ticked once
  // per state taken off the open list (as A*'s per cell), and once it says stop the search ends
  // with found = false, stopped = true. Throws std::length_error on a grid of more than
  // kMaxHeadingSearchCells cells.
  TurningPath cheapestPath(const CostGrid& grid, Cell start, Cell goal, double turn_cost, StopPoll* stop = nullptr,
                           const EndHeadings& ends = {}) {
    TurningPath result;
    stats_ = Stats{};
    if (!grid.isFree(start) || !grid.isFree(goal)) return result;
    if (grid.cellCount() > kMaxHeadingSearchCells)
      throw std::length_error("the heading search takes maps of at most " + std::to_string(kMaxHeadingSearchCells) +
                              " cells (8 states per cell numbered in 32 bits); this one has " +
                              std::to_string(grid.cellCount()));
    CellPath route;
    if (start == goal) {
      route.push_back(start);
    } else {
      detail::HeadingLabels labels(grid.cellCount());  // freed once the route is read
      const int goal_heading = search(grid, start, goal, turn_cost, ends, stop, labels, result.stopped);
      stats_.open_blocks = labels.blocksMade();
      if (goal_heading < 0) return result;
      route = routeBack(grid, labels, goal, goal_heading);
    }
    result.found = true;
    result.cost = routeCost(grid, route);
    result.length = pathLength(route);
    result.turn_steps = routeTurnSteps(route);
    result.combined_cost = combinedRouteCost(grid, route, turn_cost, ends);
    result.path = std::move(route);
    return result;
  }

  const Stats& stats() const { return stats_; }

 private:
  static std::uint32_t stateOf(std::size_t cell, int heading) {
    return static_cast<std::uint32_t>(cell << 3) | static_cast<std::uint32_t>(heading);
  }
  // The open list's final steps (the turn onto the goal heading), numbered past every state:
  // the cell number kMaxHeadingSearchCells is never a grid's.
  static constexpr std::uint32_t kFinalStep = static_cast<std::uint32_t>(kMaxHeadingSearchCells << 3);

  // A* over the states; the heading the goal was entered with, or -1 (unreachable, stopped).
  int search(const CostGrid& grid, Cell start, Cell goal, double turn_cost, const EndHeadings& ends, StopPoll* stop,
             detail::HeadingLabels& labels, bool& stopped) {
    StopPoll never;
    StopPoll& poll = stop != nullptr ? *stop : never;
    const CellWindow whole = CellWindow::whole(grid);
    const detail::SearchNeighbourhood around(grid, whole);
    double turn_price[5];  // by 45-degree steps, as combinedRouteCost prices them
    for (int k = 0; k <= 4; ++k) turn_price[k] = turn_cost * static_cast<double>(k) * kTurnStepRadians;
    const std::array<double, kDirections> start_price = headingTurnPrices(ends.start, turn_cost);
    const std::array<double, kDirections> goal_price = headingTurnPrices(ends.goal, turn_cost);
    double final_cost = std::numeric_limits<double>::infinity();  // the cheapest final step offered
    int final_heading = -1;
    open_.clear();

    // Labels the states one allowed move from `here` (grid index `index`, entered with
    // `heading`, kFromStart at the start) reaches more cheaply than their labels say.
    const auto reachFrom = [&](std::uint32_t index, Cell here, unsigned heading, double cost) {
      for (unsigned moves = around.movesFrom(here); moves != 0; moves &= moves - 1) {
        const int d = detail::lowestBit(moves);
        const std::uint32_t next = around.slotTowards(index, d);
        if (labels.settled(next, d)) continue;
        const double turn = heading == detail::HeadingLabels::kFromStart
                                ? start_price[d]
                                : turn_price[turnSteps(static_cast<int>(heading), d)];
        const double g = cost + grid.moveCostInto(next, d) + turn;
        if (labels.dominated(next, d, g, turn_price) || !labels.lower(next, d, g, heading)) continue;
        const Cell there = step(here, d);
        const double bound =
            octileDistance(there, goal) + turn_price[turnStepsAtLeast(d, goal.row - there.row, goal.col - there.col)];
        open_.push({g + bound, g, stateOf(next, d)});
      }
    };
    // Settled, or labelled again since at a lower cost (a settled state has cost +infinity).
    const auto stale = [&](const detail::SearchEntry& e) {
      if (e.slot >= kFinalStep) return e.cost > final_cost;
      const std::uint32_t cell = e.slot >> 3;
      const int heading = static_cast<int>(e.slot & 7u);
      return e.cost > labels.cost(cell, heading) || labels.settled(cell, heading);
    };

    reachFrom(static_cast<std::uint32_t>(grid.index(start)), start, detail::HeadingLabels::kFromStart, 0.0);
    const auto goal_index = static_cast<std::uint32_t>(grid.index(goal));
    detail::SearchEntry top;
    while (open_.pop(top, stale)) {
      if (poll.tick()) {  // counts stale entries too, as A* does
        stopped = true;
        return -1;
      }
      if (stale(top)) continue;
      if (top.slot >= kFinalStep) return final_heading;
      const std::uint32_t cell = top.slot >> 3;
      const int heading = static_cast<int>(top.slot & 7u);
      const bool dominated = labels.dominated(cell, heading, top.cost, turn_price);
      labels.settle(cell, heading);
      ++stats_.settled;
      if (dominated) continue;  // settled, never expanded
      if (cell == goal_index) {
        if (!ends.hasGoal()) return heading;
        const double total = top.cost + goal_price[heading];
        if (total < final_cost) {
          final_cost = total;
          final_heading = heading;
          open_.push({total, total, kFinalStep + static_cast<std::uint32_t>(heading)});
        }
        continue;  // a route through the goal and back is never cheaper
      }
      reachFrom(cell, grid.cellAt(cell), static_cast<unsigned>(heading), top.cost);
    }
    return -1;
  }

  // The cells from the start to `goal`, entered with `heading`, along the settled states.
  static CellPath routeBack(const CostGrid& grid, const detail::HeadingLabels& labels, Cell goal, int heading) {
    CellPath route;
    Cell c = goal;
    for (;;) {
      route.push_back(c);
      const unsigned from = labels.settledFrom(static_cast<std::uint32_t>(grid.index(c)), heading);
      c = Cell{c.row - kDirRow[heading], c.col - kDirCol[heading]};
      if (from == detail::HeadingLabels::kFromStart) break;
      heading = static_cast<int>(from);
    }
    route.push_back(c);  // the start
    std::reverse(route.begin(), route.end());
    return route;
  }

  alignas(64) detail::OrderedBucketQueue open_;
  Stats stats_;
};

// One search with buffers of its own.
inline TurningPath cheapestTurningPath(const CostGrid& grid, Cell start, Cell goal, double turn_cost,
                                       StopPoll* stop = nullptr, const EndHeadings& ends = {}) {
  HeadingSearch search;
  return search.cheapestPath(grid, start, goal, turn_cost, stop, ends);
}

}  // namespace eaci
