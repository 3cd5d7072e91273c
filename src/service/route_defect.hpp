// The last check of a route before it goes out to the robot, written apart from the planner
// and the smoother that made it: a grid route cell by cell, a smoothed route and the poses that
// are sent segment by segment, through every cell each straight segment passes
// (eaci::walkSegment, the one segment walk the smoother prices its shortcuts with).
#pragma once

#include <string>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_point.hpp"
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
// corner rule).
std::string drivableRouteDefect(const eaci::GridView& view, const eaci::CellPath& corners, eaci::Cell from,
                                eaci::Cell to, bool allow_corner_cutting);

// "" when every straight segment between consecutive points (cell coordinates, anywhere in the
// cells: the poses a plan sends) passes only cells `view` lets a robot cross, by the rule above;
// a point on a cell border touches the cells on both sides, which must then be passable too
// (without `allow_corner_cutting`), except the first and the last point's (the robot's and the
// goal's position: they lie in their cells). The first point's cell must be passable; one
// point: its cell.
std::string polylineDefect(const eaci::GridView& view, const eaci::CellPolyline& points, bool allow_corner_cutting);

}  // namespace eaci_service
