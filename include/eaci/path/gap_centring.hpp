// Lines through the middle of the gaps they pass (beyond the paper; issue #30). The smoothed
// route's corners are cell centres, so a line through a door an even number of cells wide runs
// half a cell off its middle, and a line that leaves a gap on a slant (towards a goal beyond it)
// passes one wall end up to 0.7 cell nearer than the cells it crosses say (smoothing.hpp). Here
// each straight line may be bent, off the cell lattice, at its narrowest point (the point of the
// line nearest an obstacle cell's centre): that point moves across the line, away from the
// obstacle, by at most `max_shift` cells, to where the two new lines keep furthest from every
// obstacle (the middle of the gap when a wall is on the other side). A bend is kept only when
// the lines' least clearance (minPolylineClearance's measure, metrics/path_metrics.hpp, outside
// a cell of their ends, where the route turns anyway) gains kMinGapGain, never past the ends'
// own, and its lines touch no obstacle and enter no cell costlier than the line's costliest:
// never nearer the walls, as the smoother's rule. Each new line is then looked at again (a line
// may pass several gaps). The corners stay: moving a corner in a gap off the walls too was
// driven and not taken (docs/ros.md, "Through the middle of a door").
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_point.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci {

// Obstacles further than this many cells from a line are not looked for: a gap is at most
// twice as wide (0.8 m on each side at 5 cm cells, beyond costmap_2d's usual inflation).
inline constexpr double kGapReach = 16.0;
// The least clearance, in cells, a bend must gain (5 mm at 5 cm cells).
inline constexpr double kMinGapGain = 0.1;
// How often a bent line's two lines are looked at again (a line may pass several gaps):
// up to 2^depth - 1 bends per line of the smoothed route.
inline constexpr int kGapBendDepth = 3;

// The obstacle cells that could be within kGapReach of a line that keeps within `shift` cells
// of a -> b: their centres, each once. `stop` is ticked by the cells looked at.
inline CellPolyline obstaclesAlong(const CostGrid& grid, const CellPoint& a, const CellPoint& b, double shift,
                                   StopPoll* stop) {
  const double reach = kGapReach + shift;
  const CellPoint d = b - a;
  const double length2 = d.squaredNorm();
  CellPolyline found;
  std::vector<std::size_t> seen;
  // The line in pieces of 8 cells, each with the square of cells within reach of it.
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::sqrt(length2) / 8.0)));
  for (int i = 0; i < pieces; ++i) {
    const CellPoint p = a + d * (static_cast<double>(i) / pieces), q = a + d * (static_cast<double>(i + 1) / pieces);
    const int r0 = std::max(0, static_cast<int>(std::floor(std::min(p.y(), q.y()) - reach)));
    const int r1 = std::min(grid.height() - 1, static_cast<int>(std::ceil(std::max(p.y(), q.y()) + reach)));
    const int c0 = std::max(0, static_cast<int>(std::floor(std::min(p.x(), q.x()) - reach)));
    const int c1 = std::min(grid.width() - 1, static_cast<int>(std::ceil(std::max(p.x(), q.x()) + reach)));
    if (stop != nullptr && r1 >= r0 && c1 >= c0 &&
        stop->tick(static_cast<std::size_t>(r1 - r0 + 1) * static_cast<std::size_t>(c1 - c0 + 1)))
      break;
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) {
        if (!grid.isBlocked(Cell{r, c})) continue;
        const CellPoint o(c, r);
        const double t = length2 > 0 ? std::clamp((o - a).dot(d) / length2, 0.0, 1.0) : 0.0;
        if ((a + t * d - o).norm() <= reach) seen.push_back(grid.index(Cell{r, c}));
      }
  }
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  for (std::size_t index : seen) found.push_back(cellPoint(grid.cellAt(index)));
  return found;
}

// The distance from p to the nearest of `obstacles` (kGapReach at most), and which.
inline double clearanceAmong(const CellPolyline& obstacles, const CellPoint& p, CellPoint* nearest = nullptr) {
  double least = kGapReach;
  for (const CellPoint& o : obstacles) {
    const double distance = (o - p).norm();
    if (distance < least) {
      least = distance;
      if (nearest != nullptr) *nearest = o;
    }
  }
  return least;
}

// Points along a -> b about a quarter cell apart (b included), none within a cell of a
// corner of the route (`a_is_corner`, `b_is_corner`: where the route turns anyway, and no bend
// moves them): where a line's clearance is measured.
template <class Visit>
void innerPointsAlong(const CellPoint& a, const CellPoint& b, bool a_is_corner, bool b_is_corner, Visit&& visit) {
  const double length = (b - a).norm();
  const int steps = static_cast<int>(std::ceil(length * 4.0));
  for (int i = 1; i <= steps; ++i) {
    const double along = length * i / steps;
    if ((a_is_corner && along < 1.0) || (b_is_corner && along > length - 1.0)) continue;
    if (!visit(a + (b - a) * (along / length))) return;
  }
}

// The smallest clearance along a -> m -> b (innerPointsAlong of each line; kGapReach when
// none is nearer). Stops early, with what it has, once it is at or below `enough_below`.
inline double polylineClearanceAmong(const CellPolyline& obstacles, const CellPoint& a, const CellPoint& m,
                                     const CellPoint& b, double enough_below = -1.0) {
  double least = kGapReach;
  const auto measure = [&](const CellPoint& p) {
    least = std::min(least, clearanceAmong(obstacles, p));
    return least > enough_below;
  };
  innerPointsAlong(a, m, true, false, measure);
  if (least > enough_below) innerPointsAlong(m, b, false, true, measure);
  return least;
}

// Whether the line a -> b touches no obstacle and enters no cell costlier than `peak`: its
// cells, sampled a quarter cell apart, and where it steps diagonally the two cells beside.
inline bool lineKeepsBelow(const CostGrid& grid, const CellPoint& a, const CellPoint& b, int peak) {
  const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() * 4.0)));
  Cell previous = cellOfPoint(a);
  for (int i = 0; i <= steps; ++i) {
    const Cell c = cellOfPoint(a + (b - a) * (static_cast<double>(i) / steps));
    for (const Cell& touched : {c, Cell{previous.row, c.col}, Cell{c.row, previous.col}})
      if (!grid.isFree(touched) || grid.cost(touched) > peak) return false;
    previous = c;
  }
  return true;
}

// The point `from` of the line a -> b moved by up to `max_shift` cells along `across` (in steps of 0.05 cell) to
// where the lines a -> m -> b keep furthest from `obstacles`, if that gains kMinGapGain over
// `before` (their clearance through `from`) without passing `ends` (a's and b's own), and they
// touch no obstacle and enter no cell costlier than the line's costliest; else nothing.
inline std::optional<CellPoint> widestPointAcross(const CostGrid& grid, const CellPolyline& obstacles,
                                                  const CellPoint& a, const CellPoint& from, const CellPoint& b,
                                                  const CellPoint& across, double before, double ends,
                                                  double max_shift, StopPoll* stop) {
  int peak = 0;  // the costliest cell of the line a -> b (`from` lies on it): the bent lines enter none costlier
  const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() * 4.0)));
  for (int i = 0; i <= steps; ++i) peak = std::max<int>(peak, grid.cost(cellOfPoint(a + (b - a) * (double(i) / steps))));
  const std::size_t work = obstacles.size() * static_cast<std::size_t>((from - a).norm() + (b - from).norm() + 1) * 4;
  double best = before + kMinGapGain;
  std::optional<CellPoint> widest;
  constexpr double kShiftStep = 0.05;
  for (double shift = kShiftStep; shift <= max_shift + 1e-9 && best < ends; shift += kShiftStep) {
    const CellPoint m = from + shift * across;
    if (stop != nullptr && stop->tick(work)) break;
    if (!lineKeepsBelow(grid, a, m, peak) || !lineKeepsBelow(grid, m, b, peak)) break;
    const double clearance = std::min(ends, polylineClearanceAmong(obstacles, a, m, b, best));
    if (clearance > best) best = clearance, widest = m;
  }
  return widest;
}

// The line a -> b bent through the gaps it passes (above), up to `depth` levels: the bends,
// appended to `out` (a and b not).
inline void bendThroughGaps(const CostGrid& grid, CellPoint a, CellPoint b, double max_shift, int depth,
                            StopPoll* stop, CellPolyline& out) {
  const double length = (b - a).norm();
  if (depth <= 0 || length < 3.0 || (stop != nullptr && stop->stopped())) return;
  const CellPolyline obstacles = obstaclesAlong(grid, a, b, max_shift, stop);
  if (obstacles.empty() || (stop != nullptr && stop->stopped())) return;
  // The narrowest point and the obstacle nearest it.
  CellPoint narrowest = a, nearest = a;
  double before = kGapReach;
  innerPointsAlong(a, b, true, true, [&](const CellPoint& p) {
    CellPoint o = p;
    const double clearance = clearanceAmong(obstacles, p, &o);
    if (clearance < before) before = clearance, narrowest = p, nearest = o;
    return true;
  });
  // A line no narrower inside than at its ends is left as it is (it only leaves a corner near a
  // wall, which no bend moves), and no bend makes it wider there than at its ends.
  const double ends = std::min(clearanceAmong(obstacles, a), clearanceAmong(obstacles, b));
  if (before + kMinGapGain >= ends) return;
  CellPoint across(-(b - a).y() / length, (b - a).x() / length);  // across the line, away from it
  if (across.dot(narrowest - nearest) < 0) across = -across;
  const std::optional<CellPoint> bend =
      widestPointAcross(grid, obstacles, a, narrowest, b, across, before, ends, max_shift, stop);
  if (!bend) return;
  bendThroughGaps(grid, a, *bend, max_shift, depth - 1, stop, out);
  out.push_back(*bend);
  bendThroughGaps(grid, *bend, b, max_shift, depth - 1, stop, out);
}

// The smoothed route's corners as points, each line bent through the gaps it passes (above);
// the corners themselves stay. `max_shift` cells (0 = the corners as they are). Once `stop`
// says stop the lines not yet looked at stay straight.
inline CellPolyline centreInGaps(const CostGrid& grid, const CellPath& corners, double max_shift,
                                 StopPoll* stop = nullptr) {
  const CellPolyline points = cellPolyline(corners);
  if (!(max_shift > 0) || points.empty()) return points;
  for (const Cell& c : corners)
    if (!grid.contains(c)) return points;
  CellPolyline out{points.front()};
  for (std::size_t k = 1; k < points.size(); ++k) {
    if (stop == nullptr || !stop->stopped()) bendThroughGaps(grid, out.back(), points[k], max_shift, kGapBendDepth, stop, out);
    out.push_back(points[k]);
  }
  return out;
}

}  // namespace eaci
