// The last check of a route before it goes out to the robot, written apart from the planner
// and the smoother that made it: a grid route cell by cell, a smoothed route segment by segment
// through every cell its straight segments pass.
#pragma once

#include <string>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"

namespace eaci_service {

// "" when `route` runs from `from` to `to` by 8-neighbour moves over cells `view` lets a robot
// cross, diagonal moves past a blocked cell only with `allow_corner_cutting` (the move rule);
// else what is wrong. drivableRouteDefect on moves of one cell, after a check for jumps.
std::string routeDefect(const eaci::GridView& view, const eaci::CellPath& route, eaci::Cell from, eaci::Cell to,
                        bool allow_corner_cutting);

// "" when the polyline of cell centres `corners` runs from `from` to `to` and each straight
// segment between consecutive corners passes only cells `view` lets a robot cross; else which
// segment fails and where. A segment passes every cell its line crosses the inside of; where
// the line goes exactly through a cell corner it moves diagonally, and without
// `allow_corner_cutting` both cells beside that corner must be passable too (the move rule's
// corner rule). Exact integer arithmetic: no rounding decides a corner.
std::string drivableRouteDefect(const eaci::GridView& view, const eaci::CellPath& corners, eaci::Cell from,
                                eaci::Cell to, bool allow_corner_cutting);

}  // namespace eaci_service
