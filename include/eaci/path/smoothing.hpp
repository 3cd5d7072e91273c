// A drivable route from a grid route: line-of-sight shortcuts over the 8-connected cells
// (beyond the paper; off for its benchmarks). A shortcut is taken only when the straight
// segment touches no obstacle cell, corners included, costs no more than the stretch of route
// it replaces, and enters no cell costlier than the costliest cell of that stretch: the
// smoothed route is never costlier, and on a costmap passes no cell nearer the walls, than the
// grid route (on a map without costs only the first two conditions bite). The rule measures
// cells: a line may pass up to 0.7 cell nearer a wall than the centres of the cells it passes
// (minPolylineClearance, metrics/path_metrics.hpp, measures the lines; a bound on the costs
// interpolated between the centres was tried and not taken: docs/notebook/2026-12-05-drive-tuning-beside-navfn.md). A tolerance (the smooth_tolerance parameter) relaxes the last two by a factor, below.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <vector>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/end_headings.hpp"
#include "eaci/grid/line_clearance.hpp"
#include "eaci/grid/segment_walk.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci {

// What driving a straight segment between two cell centres costs, from one walk along it.
struct SegmentCost {
  // Each cell's length inside the segment, weighted like a move into that cell
  // (CostGrid::moveCostInto per unit length); +infinity if it touches an obstacle or leaves the map.
  double cost = 0.0;
  // The highest cell cost (CostGrid::cost) among the cells it passes through or touches at a
  // corner; 255 if it touches an obstacle or leaves the map.
  int peak = 0;
};

// The segment's cost and peak. The walk ends early once the cost so far is above `cost_bound`
// or the peak above `peak_bound` (each then already above its bound, as the whole segment's
// would be: costs only add up); the defaults walk the whole segment.
inline SegmentCost segmentCostAndPeak(const CostGrid& grid, Cell from, Cell to,
                                      double cost_bound = std::numeric_limits<double>::infinity(),
                                      int peak_bound = 255) {
  SegmentCost segment;
  traverseSegment(from, to, [&](Cell c, double length) {
    if (!grid.isFree(c)) {
      segment.cost = std::numeric_limits<double>::infinity();
      segment.peak = 255;
      return false;
    }
    segment.cost += length * grid.moveCostInto(grid.index(c), 0);  // direction 0: a straight move, length 1
    segment.peak = std::max<int>(segment.peak, grid.cost(c));
    return segment.cost <= cost_bound && segment.peak <= peak_bound;
  });
  return segment;
}

// The segment's cost alone (SegmentCost::cost).
inline double segmentCost(const CostGrid& grid, Cell from, Cell to) { return segmentCostAndPeak(grid, from, to).cost; }

// Greedy string pulling: from each kept cell, the farthest later cell of the route reachable
// by an allowed shortcut (the search stops at the first that is not). With `tolerance` t > 0 a
// shortcut may cost up to (1 + t) x the stretch it replaces and enter cells up to (1 + t) x the
// stretch's costliest cell (never an obstacle): on costmap_2d's inflation, 252 exp(-k (d - r)),
// that lets it pass at most ln(1 + t) / k nearer the walls than the stretch, which rounds the
// corners a cost-aware route keeps in the middle of a gap. Returns the kept cells,
// start and goal included; consecutive kept cells are joined by straight segments.
// A route that is not 8-connected is returned as it is. The work is up to quadratic in the
// route's length (each shortcut tried is walked cell by cell, once, until it fails): `stop` is
// ticked by the cells each try spans, and once it says stop the route is smoothed up to where
// it got and goes on cell by cell from there (as valid as the whole smoothed route).
// With end headings and turn_cost > 0 (PlanOptions::end_headings) a shortcut from the start or
// into the goal also answers for its turn from the start heading or onto the goal heading: it
// may cost what the stretch allows plus turn_cost x (the turn of the stretch's end move - its
// own). With a goal heading the last segment is chosen first, from the earliest cell of the
// route whose shortcut into the goal is allowed (scanning back from the goal, up to the first
// that is not), and the rest is pulled up to that cell: a long straight segment that cuts into
// the goal across its heading does not replace the route's last leg (issue #30: the car crawls
// into a goal it enters far off its yaw).
inline CellPath smoothRoute(const CostGrid& grid, const CellPath& route, StopPoll* stop = nullptr,
                            double tolerance = 0.0, double turn_cost = 0.0, const EndHeadings& ends = {}) {
  if (route.size() < 3 || !std::isfinite(routeCost(grid, route))) return route;
  const std::size_t last = route.size() - 1;
  const auto moveCost = [&](std::size_t k) {  // the move into route[k]
    const int dir = directionBetween(route[k - 1], route[k]);
    return dir < 0 ? std::numeric_limits<double>::infinity() : grid.moveCost(route[k - 1], dir);
  };
  const bool priced_start = turn_cost > 0 && ends.hasStart();
  const bool priced_goal = turn_cost > 0 && ends.hasGoal();
  const double start_turn = priced_start ? angleBetween(ends.start, headingOf(route[0], route[1])) : 0.0;
  const double goal_turn = priced_goal ? angleBetween(ends.goal, headingOf(route[last - 1], route[last])) : 0.0;
  // Whether the straight segment route[i] -> route[j] may replace the stretch between them,
  // which costs `stretch_cost` and enters no cell costlier than `stretch_peak`.
  const auto allowed = [&](std::size_t i, std::size_t j, double stretch_cost, int stretch_peak) {
    double cost_bound = stretch_cost * (1.0 + tolerance) + 1e-9;
    if (priced_start && i == 0) cost_bound += turn_cost * (start_turn - angleBetween(ends.start, headingOf(route[i], route[j])));
    if (priced_goal && j == last) cost_bound += turn_cost * (goal_turn - angleBetween(ends.goal, headingOf(route[i], route[j])));
    const int peak_bound = std::min(254, static_cast<int>(std::floor(stretch_peak * (1.0 + tolerance) + 1e-9)));
    const SegmentCost shortcut = segmentCostAndPeak(grid, route[i], route[j], cost_bound, peak_bound);
    return shortcut.cost <= cost_bound && shortcut.peak <= peak_bound;
  };
  std::size_t pulled_to = last;  // the greedy pass below smooths route[0 .. pulled_to]
  if (priced_goal) {
    double stretch_cost = moveCost(last);
    int stretch_peak = std::max<int>(grid.cost(route[last - 1]), grid.cost(route[last]));
    pulled_to = last - 1;
    for (std::size_t k = last - 1; k-- > 0;) {
      if (stop != nullptr && stop->tick(last - k)) break;  // a walk of about last - k cells
      stretch_cost += moveCost(k + 1);
      stretch_peak = std::max<int>(stretch_peak, grid.cost(route[k]));
      if (!allowed(k, last, stretch_cost, stretch_peak)) break;
      pulled_to = k;
    }
  }
  CellPath kept{route.front()};
  std::size_t i = 0;
  while (i < pulled_to) {
    std::size_t best = i + 1;
    double stretch_cost = moveCost(i + 1);
    int stretch_peak = std::max<int>(grid.cost(route[i]), grid.cost(route[i + 1]));
    for (std::size_t j = i + 2; j <= pulled_to; ++j) {
      if (stop != nullptr && stop->tick(j - i)) {  // a walk of about j - i cells
        kept.insert(kept.end(), route.begin() + static_cast<std::ptrdiff_t>(i) + 1, route.end());
        return kept;
      }
      stretch_cost += moveCost(j);
      stretch_peak = std::max<int>(stretch_peak, grid.cost(route[j]));
      if (!allowed(i, j, stretch_cost, stretch_peak)) break;
      best = j;
    }
    kept.push_back(route[best]);
    i = best;
  }
  if (pulled_to < last) kept.push_back(route[last]);
  return kept;
}

// What the polyline through `corners` costs (segmentCostAndPeak, summed) and its costliest
// cell: +infinity and 255 once a segment touches an obstacle.
inline SegmentCost polylineCostAndPeak(const CostGrid& grid, const CellPath& corners) {
  SegmentCost total;
  for (std::size_t k = 1; k < corners.size(); ++k) {
    if (corners[k - 1] == corners[k]) continue;
    const SegmentCost segment = segmentCostAndPeak(grid, corners[k - 1], corners[k]);
    total.cost += segment.cost;
    total.peak = std::max(total.peak, segment.peak);
    if (!std::isfinite(total.cost)) break;
  }
  return total;
}

// The cell nearest the point `distance` cells of length from `from` towards `to` (at most `to`).
inline Cell cellTowards(Cell from, Cell to, double distance) {
  const double length = std::hypot(to.col - from.col, to.row - from.row);
  const double t = length > 0 ? std::min(1.0, distance / length) : 0.0;
  return Cell{static_cast<int>(std::lround(from.row + t * (to.row - from.row))),
              static_cast<int>(std::lround(from.col + t * (to.col - from.col)))};
}

// Corners of a smoothed route closer together than this many cells round as one bend: the
// smoother often turns through 90 degrees in two 45-degree corners one diagonal cell apart.
inline constexpr double kBendCornerSpacing = 3.0;

// Corner rounding looks this far (cells) for the clearance a cut has to keep: a bend in the cost
// band of a costmap's inflation is nearer a wall than that.
inline constexpr double kCornerClearanceReach = 32.0;

// Whether the cut a -> b passes no nearer an obstacle than the corner it cuts off, a v_i .. v_j
// b, whose bend v_i .. v_j keeps `bend_clearance` (polylineClearanceWithin up to
// kCornerClearanceReach: measured once a bend, the same for every cut of it).
inline bool cutKeepsClearance(const CostGrid& grid, Cell a, Cell v_i, Cell v_j, Cell b, double bend_clearance) {
  const double keep = segmentClearanceWithin(grid, cellPoint(v_j), cellPoint(b),
                                             segmentClearanceWithin(grid, cellPoint(a), cellPoint(v_i), bend_clearance));
  return segmentClearanceWithin(grid, cellPoint(a), cellPoint(b), keep) >= keep - 1e-9;
}

// Rounds the bends of a smoothed route (smoothRoute's kept cells), `passes` times, each pass
// bend by bend from the start. A bend is a corner, or corners less than kBendCornerSpacing
// apart, v_i .. v_j between p (before it) and n (after it). It is cut off by one segment from
// a cell a on v_i -> p to a cell b on v_j -> n, both d cells of length from the bend, when
// p a b n is allowed in place of p v_i .. v_j n by the smoother's rule with the corner it cuts
// off, a v_i .. v_j b, as the stretch replaced: it touches no obstacle, costs up to
// (1 + tolerance) x as much as p v_i .. v_j n, and the cut a -> b enters no cell costlier than
// (1 + tolerance) x the costliest of the corner (not of the whole stretch from p, which may
// start in the band; issue #30), and, where the corner is in an obstacle's cost band, passes no
// nearer an obstacle than the corner it cuts off does, up to kCornerClearanceReach (the one
// clearance measure, grid/line_clearance.hpp): the rounded route's clearance is never below
// the route's, and a cut that would start beside a door post and turn towards it starts
// farther on (the cost rule alone let such cuts pass door posts 2 cm nearer than the bend,
// and the car, cutting inside the bend, nearer still). d is
// the largest allowed of d_max, d_max / 2, d_max / 4, ... down to one cell, d_max = min(|v_i p|,
// |v_j n| / 2) (|v_i p| is what the previous cut left of that segment; half of v_j n is left
// for the next bend). A pass splits a bend's turn in two (90 degrees become two corners of
// about 45), which a car takes with less slowing than one sharp bend (docs/notebook/2026-12-01-driving-to-the-lab-goals.md). Start and goal stay. `stop` is ticked by the cells each try walks; once it
// says stop the rest stays as it is. `keep_last_leg` (a goal heading is priced: smoothRoute)
// leaves the bend before the goal as it is, so the route arrives along its whole last leg and
// not along a cut that shortens it.
inline CellPath roundCorners(const CostGrid& grid, const CellPath& corners, int passes, double tolerance = 0.0,
                             StopPoll* stop = nullptr, bool keep_last_leg = false) {
  const auto distance = [](Cell a, Cell b) { return std::hypot(a.col - b.col, a.row - b.row); };
  CellPath route = corners;
  for (int pass = 0; pass < passes && route.size() >= 3; ++pass) {
    CellPath rounded{route.front()};
    std::size_t i = 1;
    while (i + 1 < route.size()) {
      std::size_t j = i;  // the bend: route[i .. j]
      while (j + 2 < route.size() && distance(route[j], route[j + 1]) < kBendCornerSpacing) ++j;
      const Cell p = rounded.back(), n = route[j + 1];
      const double to_p = distance(route[i], p), to_n = distance(route[j], n);
      CellPath replaced{p};
      replaced.insert(replaced.end(), route.begin() + static_cast<std::ptrdiff_t>(i),
                      route.begin() + static_cast<std::ptrdiff_t>(j) + 1);
      replaced.push_back(n);
      bool cut = false;
      const std::size_t walk = static_cast<std::size_t>(to_p + to_n) + 1;
      const bool last_bend = j + 2 == route.size();
      double bend_clearance = -1.0;  // of route[i .. j], measured when a cut first asks
      const auto keepsClearance = [&](Cell a, Cell b) {
        if (bend_clearance < 0) {
          const CellPath bend(route.begin() + static_cast<std::ptrdiff_t>(i), route.begin() + static_cast<std::ptrdiff_t>(j) + 1);
          bend_clearance = polylineClearanceWithin(grid, bend, kCornerClearanceReach);
        }
        return cutKeepsClearance(grid, a, route[i], route[j], b, bend_clearance);
      };
      if (!(keep_last_leg && last_bend) && (stop == nullptr || !stop->tick(walk))) {
        const SegmentCost bend = polylineCostAndPeak(grid, replaced);
        const double cost_bound = bend.cost * (1.0 + tolerance) + 1e-9;
        for (double d = std::min(to_p, to_n / 2); std::isfinite(bend.cost) && d >= 1.0 && !cut; d /= 2) {
          const Cell a = cellTowards(route[i], p, d), b = cellTowards(route[j], n, d);
          if (a == b || a == p || a == route[i] || b == route[j]) continue;  // rounded onto a corner: try nearer
          if (stop != nullptr && stop->tick(walk)) break;
          CellPath corner{a};
          corner.insert(corner.end(), replaced.begin() + 1, replaced.end() - 1);
          corner.push_back(b);
          const int corner_peak = polylineCostAndPeak(grid, corner).peak;
          const int peak_bound = std::min(254, static_cast<int>(std::floor(corner_peak * (1.0 + tolerance) + 1e-9)));
          const SegmentCost chord = segmentCostAndPeak(grid, a, b);
          const double cut_cost = segmentCost(grid, p, a) + chord.cost + segmentCost(grid, b, n);
          // A corner through cells of cost 0 alone is not measured: its cut, through cells of cost 0
          // too, stays beyond every obstacle's cost band.
          if (cut_cost <= cost_bound && chord.peak <= peak_bound && (corner_peak == 0 || keepsClearance(a, b))) {
            rounded.push_back(a);
            rounded.push_back(b);
            cut = true;
          }
        }
      }
      if (!cut) rounded.insert(rounded.end(), replaced.begin() + 1, replaced.end() - 1);
      i = j + 1;
    }
    rounded.push_back(route.back());
    route = std::move(rounded);
  }
  return route;
}

}  // namespace eaci
