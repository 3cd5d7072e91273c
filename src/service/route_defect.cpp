#include "route_defect.hpp"

#include <cstdlib>
#include <vector>

#include "eaci/grid/segment_walk.hpp"
#include "eaci/io/text.hpp"

namespace eaci_service {
namespace {

std::string describe(eaci::Cell c) { return "(row " + std::to_string(c.row) + ", col " + std::to_string(c.col) + ")"; }

std::string describe(const eaci::CellPoint& p) {
  return "(row " + eaci::formatNumber(p.y(), 3) + ", col " + eaci::formatNumber(p.x(), 3) + ")";
}

// "" when the straight segment from `a` to `b` passes only passable cells (eaci::walkSegment):
// every cell it crosses, and without `allow_corner_cutting` every cell it touches at a corner
// or with an end on a border (`b`'s only with `end_touches`).
std::string segmentDefect(const eaci::GridView& view, const eaci::CellPoint& a, const eaci::CellPoint& b,
                          bool allow_corner_cutting, bool end_touches = true) {
  std::string defect;
  bool first = true;
  std::vector<eaci::Cell> touched;  // cells touched at a corner or a border since the last one crossed
  const auto touchedDefect = [&]() -> std::string {
    for (const eaci::Cell& c : touched) {
      if (view.isFree(c)) continue;
      if (touched.size() >= 2 && (!view.isFree(touched[0]) || !view.isFree(touched[1])))
        return "it passes a blocked cell's corner between " + describe(touched[0]) + " and " + describe(touched[1]);
      return "it touches the blocked cell " + describe(c);
    }
    return "";
  };
  eaci::walkSegment(a, b, [&](eaci::Cell c, double length) {
    if (first || length > 0) {
      if (!allow_corner_cutting) defect = touchedDefect();
      touched.clear();
      if (defect.empty() && !view.isFree(c))
        defect = (first ? "it starts in the blocked cell " : "it crosses the blocked cell ") + describe(c);
      first = false;
    } else {
      touched.push_back(c);
    }
    return defect.empty();
  });
  if (defect.empty() && !allow_corner_cutting && end_touches) defect = touchedDefect();
  return defect;
}

}  // namespace

std::string routeDefect(const eaci::GridView& view, const eaci::CellPath& route, eaci::Cell from, eaci::Cell to,
                        bool allow_corner_cutting) {
  for (std::size_t i = 1; i < route.size(); ++i) {
    const int dr = route[i].row - route[i - 1].row, dc = route[i].col - route[i - 1].col;
    if (std::abs(dr) > 1 || std::abs(dc) > 1 || (dr == 0 && dc == 0)) return "it jumps at cell " + std::to_string(i);
  }
  // Each move is a segment of one cell: the segment walk checks its cells and the corner rule.
  return drivableRouteDefect(view, route, from, to, allow_corner_cutting);
}

std::string drivableRouteDefect(const eaci::GridView& view, const eaci::CellPath& corners, eaci::Cell from,
                                eaci::Cell to, bool allow_corner_cutting) {
  if (corners.empty() || !(corners.front() == from) || !(corners.back() == to)) return "it does not join start and goal";
  if (corners.size() == 1 && !view.isFree(corners.front())) return "its only cell is blocked";
  for (std::size_t i = 1; i < corners.size(); ++i) {
    const std::string defect =
        segmentDefect(view, eaci::cellPoint(corners[i - 1]), eaci::cellPoint(corners[i]), allow_corner_cutting);
    if (!defect.empty())
      return "segment " + std::to_string(i) + " of " + std::to_string(corners.size() - 1) + ", " +
             describe(corners[i - 1]) + " to " + describe(corners[i]) + ": " + defect;
  }
  return "";
}

std::string polylineDefect(const eaci::GridView& view, const eaci::CellPolyline& points, bool allow_corner_cutting) {
  if (points.empty()) return "it has no points";
  if (points.size() == 1 && !view.isFree(eaci::cellOfPoint(points.front()))) return "its only point is in a blocked cell";
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (!points[i - 1].allFinite() || !points[i].allFinite()) return "point " + std::to_string(i) + " is not finite";
    // The last point lies in its cell however it touches the cells beside (the goal: the frame's rule).
    const std::string defect =
        segmentDefect(view, points[i - 1], points[i], allow_corner_cutting, i + 1 < points.size());
    if (!defect.empty())
      return "segment " + std::to_string(i) + " of " + std::to_string(points.size() - 1) + ", " +
             describe(points[i - 1]) + " to " + describe(points[i]) + ": " + defect;
  }
  return "";
}

}  // namespace eaci_service
