// Where a grid lies in the world: the one world <-> cell transform, used by the map I/O
// (OccupancyMap) and by the ROS layer (OccupancyGrid, costmap_2d).
//
// map_server's and costmap_2d's convention: the origin is the world position of the outer
// corner of the bottom-left cell; x runs along the columns, y up the rows, `resolution`
// metres per cell. Cells count rows from the top (eaci::Cell, row 0 = top), so the row
// flips: a point `from_bottom` whole cells above the origin is in row height - 1 - from_bottom.
// Like costmap_2d, positions ignore the origin's yaw; it is kept for reference.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <optional>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/cell_point.hpp"
#include "eaci/grid/cell_numbering.hpp"

namespace eaci {

struct MapFrame {
  int width = 0;            // cells
  int height = 0;           // cells
  double resolution = 1.0;  // metres per cell
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // bottom-left corner of the bottom-left cell
  double origin_yaw = 0.0;                           // radians; kept for reference, positions ignore it

  // The cell containing the world point, or nothing when the point lies off the grid, is not
  // finite, or the resolution is not positive. A point on a cell's left or bottom edge is in
  // that cell, so x = origin.x + width * resolution is off the grid.
  std::optional<Cell> worldToCell(const Eigen::Vector2d& point) const {
    if (!point.allFinite() || !(resolution > 0)) return std::nullopt;
    const Eigen::Vector2d cells = ((point - origin) / resolution).array().floor();
    const double col = cells.x();
    const double from_bottom = cells.y();
    if (col < 0 || from_bottom < 0 || col >= width || from_bottom >= height) return std::nullopt;
    return Cell{height - 1 - static_cast<int>(from_bottom), static_cast<int>(col)};
  }

  // World position of the cell's centre: the paper's cell centre (Eq. 3-4) in metres, moved
  // to the origin.
  Eigen::Vector2d cellToWorld(Cell cell) const { return origin + cellCentre(cell, height, resolution); }
  // World position of a point in cell coordinates (CellPoint: x = column, y = row, centres at
  // whole numbers), as cellToWorld of the cell it lies in, off the centre by as much.
  Eigen::Vector2d pointToWorld(const CellPoint& p) const {
    return origin + Eigen::Vector2d((p.x() + 0.5) * resolution, (height - p.y() - 0.5) * resolution);
  }
  // The world point in cell coordinates (pointToWorld's inverse); it may lie off the grid.
  CellPoint worldToPoint(const Eigen::Vector2d& point) const {
    const Eigen::Vector2d cells = (point - origin) / resolution;
    return {cells.x() - 0.5, height - cells.y() - 0.5};
  }
};

}  // namespace eaci
