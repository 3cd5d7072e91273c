// A point in cell coordinates, off the cell lattice: x = column, y = row (0 = top), a cell's
// centre at whole numbers.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <vector>

#include "eaci/grid/cell.hpp"

namespace eaci {

using CellPoint = Eigen::Vector2d;
using CellPolyline = std::vector<CellPoint>;

inline CellPoint cellPoint(Cell c) { return {static_cast<double>(c.col), static_cast<double>(c.row)}; }
// The cell a point lies in.
inline Cell cellOfPoint(const CellPoint& p) {
  return Cell{static_cast<int>(std::lround(p.y())), static_cast<int>(std::lround(p.x()))};
}
inline CellPolyline cellPolyline(const CellPath& corners) {
  CellPolyline points;
  points.reserve(corners.size());
  for (const Cell& c : corners) points.push_back(cellPoint(c));
  return points;
}

}  // namespace eaci
