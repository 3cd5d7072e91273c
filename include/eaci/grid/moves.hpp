// The eight moves of the grid model and their lengths (straight 1, diagonal sqrt 2).
#pragma once

#include <array>
#include <cstdlib>

#include "eaci/grid/cell.hpp"

namespace eaci {

constexpr int kDirections = 8;
constexpr double kSqrt2 = 1.41421356237309504880;

// Directions counter-clockwise from east; direction d points at d * 45 degrees
// (row grows downwards, so "north" is row - 1).
constexpr std::array<int, kDirections> kDirRow = {0, -1, -1, -1, 0, 1, 1, 1};
constexpr std::array<int, kDirections> kDirCol = {1, 1, 0, -1, -1, -1, 0, 1};

inline bool isDiagonal(int dir) { return (dir & 1) != 0; }
inline double stepLength(int dir) { return isDiagonal(dir) ? kSqrt2 : 1.0; }
inline Cell step(Cell c, int dir) { return Cell{c.row + kDirRow[dir], c.col + kDirCol[dir]}; }

// Direction of the move a -> b between 8-neighbours, or -1 if they are not neighbours.
inline int directionBetween(Cell a, Cell b) {
  const int dr = b.row - a.row;
  const int dc = b.col - a.col;
  for (int d = 0; d < kDirections; ++d) {
    if (kDirRow[d] == dr && kDirCol[d] == dc) return d;
  }
  return -1;
}

// Number of 45-degree steps between two move directions: 0 (straight on) .. 4 (reversal).
inline int turnSteps(int from_dir, int to_dir) {
  const int diff = std::abs(from_dir - to_dir);
  return diff <= 4 ? diff : kDirections - diff;
}

}  // namespace eaci
