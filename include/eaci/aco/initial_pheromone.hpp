// Non-uniform initial pheromone between consecutive islands (Eq. 18-22).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "eaci/aco/colony_region.hpp"
#include "eaci/aco/pheromone_field.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/cell_numbering.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci {

// Line A x + B y + C = 0 through the centres of two cells (Eq. 19), in cell units.
struct Line {
  double a = 0.0, b = 0.0, c = 0.0;

  static Line through(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return Line{q.y() - p.y(), p.x() - q.x(), q.x() * p.y() - p.x() * q.y()};
  }

  // |A x + B y + C| / sqrt(A^2 + B^2): distance of a point from the line.
  double distanceTo(const Eigen::Vector2d& p) const { return std::abs(a * p.x() + b * p.y() + c) / std::hypot(a, b); }
};

// Eq. 18-20: pheromone of edge i -> j of a favourable region, the inverse distance of the
// edge midpoint from the line through the region's islands; if the midpoint is on the
// line, the inverse distance of node i; if i is on the line too, +infinity.
inline double regionEdgePheromone(const Line& line, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  constexpr double kOnLine = 1e-12;
  const Eigen::Vector2d mid = (from + to) / 2.0;
  const double d_mid = line.distanceTo(mid);
  if (d_mid > kOnLine) return 1.0 / d_mid;
  const double d_from = line.distanceTo(from);
  if (d_from > kOnLine) return 1.0 / d_from;
  return std::numeric_limits<double>::infinity();
}

// Eq. 21-22 over the colony's cells (`cells`; ColonyRegion::wholeMap: the whole map, as in the
// paper; edges from cells outside are not stored). The favourable region FG_z is the
// axis-aligned rectangle with islands L_z and L_{z+1} at opposite corners; an edge lies in it when both cells
// do. Edges in a region take their Eq. 18-20 value (+infinity -> lambda * max tau0);
// every other edge takes min tau0. An edge in two regions takes the larger value.
// When no region edge has a finite value (every region a single line of cells), max tau0
// and min tau0 are taken as 1.
// `reuse`: a field whose memory the new one takes over (PheromoneField::reset). `stop`: ticked
// once per row of a favourable region; stopped, `reuse` comes back untouched (the caller reads
// stop->stopped()).
inline PheromoneField initialIslandPheromone(const CostGrid& grid, const ColonyRegion& cells,
                                             const std::vector<Cell>& islands, double lambda, double alpha,
                                             PheromoneField reuse = {}, StopPoll* stop = nullptr) {
  // (edge, value) of every region edge, in the order the regions are visited; the regions are
  // small, so this is much smaller than a value per edge of the map.
  std::vector<std::pair<std::size_t, double>> region_value;
  double max_tau0 = -std::numeric_limits<double>::infinity();
  double min_tau0 = std::numeric_limits<double>::infinity();
  for (std::size_t z = 0; z + 1 < islands.size(); ++z) {
    const Cell p = islands[z], q = islands[z + 1];
    const Line line = Line::through(cellCentre(p, grid.height()), cellCentre(q, grid.height()));
    const int r0 = std::min(p.row, q.row), r1 = std::max(p.row, q.row);
    const int c0 = std::min(p.col, q.col), c1 = std::max(p.col, q.col);
    auto in_region = [&](Cell c) { return c.row >= r0 && c.row <= r1 && c.col >= c0 && c.col <= c1; };
    for (int r = r0; r <= r1; ++r) {
      if (stop != nullptr && stop->tick(static_cast<std::size_t>(c1 - c0 + 1))) return reuse;
      for (int c = c0; c <= c1; ++c) {
        const Cell from{r, c};
        const unsigned moves = grid.movesFrom(from);
        for (int d = 0; d < kDirections; ++d) {
          const Cell to = step(from, d);
          if (!in_region(to) || (moves & (1u << d)) == 0) continue;
          const double value =
              regionEdgePheromone(line, cellCentre(from, grid.height()), cellCentre(to, grid.height()));
          if (std::isfinite(value)) {
            max_tau0 = std::max(max_tau0, value);
            min_tau0 = std::min(min_tau0, value);
          }
          const std::uint32_t from_cell = cells.regionIndex(from);
          if (from_cell != ColonyRegion::kNone)
            region_value.emplace_back(std::size_t{from_cell} * kDirections + static_cast<std::size_t>(d), value);
        }
      }
    }
  }
  if (!std::isfinite(max_tau0)) max_tau0 = min_tau0 = 1.0;

  // An edge in two regions: its largest value, +infinity above every finite one.
  PheromoneField field = std::move(reuse);
  field.reset(cells.size(), min_tau0, alpha);
  std::vector<std::uint8_t> on_line(cells.size(), 0);  // bit d: the edge took Eq. 21's lambda * max tau0
  for (const auto& [edge, value] : region_value) {
    const std::size_t cell = edge / kDirections;
    const int d = static_cast<int>(edge % kDirections);
    const auto bit = static_cast<std::uint8_t>(1u << d);
    if (on_line[cell] & bit) continue;
    if (std::isfinite(value)) {
      field.raise(cell, d, value);
    } else {
      on_line[cell] |= bit;
      field.set(cell, d, lambda * max_tau0);
    }
  }
  field.refreshChanged();
  return field;
}

}  // namespace eaci
