// What one unit of turn_cost is worth (issue #30): turn_cost prices a radian of heading change
// as that many cells of going. In a free cell (the default), a value that suits open floor
// (where a cell costs 1) is far too small in a cluttered lab, whose every cell sits in the
// inflation band and costs 3-4 x a free one, and a value that suits the lab makes the route
// on open floor take metres of detour to save a corner. In the route's cell, a radian costs
// turn_cost x the cost of the average cell of the cheapest route between start and goal
// (routeCellCost: its cost / its length, moves priced as every planner prices them, turns
// not), so one value prices turns alike on both: the plan uses turn_cost x that as its turn
// price (PlanResult::turn_price) and is otherwise the plan of that turn_cost in free cells.
#pragma once

#include <algorithm>
#include <cmath>

namespace eaci {

enum class TurnCostUnit {
  kFreeCell,   // turn_cost x radians, as it is
  kRouteCell,  // turn_cost x radians x routeCellCost of the cheapest route between start and goal
};

inline const char* toString(TurnCostUnit u) { return u == TurnCostUnit::kFreeCell ? "free_cell" : "route_cell"; }

// The cost of a route's average cell: its cost (the sum of its move costs) / its length, both
// in cells; at least 1 on any grid (no move costs less than its length); 1 when there is no
// route to measure (a length of 0, or not finite).
inline double routeCellCost(double cost, double length) {
  if (!(length > 0) || !std::isfinite(cost) || !std::isfinite(length)) return 1.0;
  return std::max(1.0, cost / length);
}

}  // namespace eaci
