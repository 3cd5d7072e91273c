// The eight moves of the grid model and their lengths (straight 1, diagonal sqrt 2), and a
// route's length and heading change.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
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

// The length in cells of the step a -> b: 1 or sqrt 2 between 8-neighbours, else (a jump no
// planner returns) the straight line between the cell centres.
inline double stepLengthBetween(Cell a, Cell b) {
  const int dir = directionBetween(a, b);
  if (dir >= 0) return stepLength(dir);
  return std::hypot(static_cast<double>(b.col - a.col), static_cast<double>(b.row - a.row));
}

// A route's length in cells: the sum of its steps' lengths (stepLengthBetween), 0 for one cell.
inline double pathLength(const CellPath& path) {
  double length = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) length += stepLengthBetween(path[k - 1], path[k]);
  return length;
}

// The move rule. A move needs a free target cell; without corner cutting a diagonal move also
// needs both cells beside it free (the two straight neighbours that share its corner), with
// corner cutting (the paper's benchmark rule) it does not. Given which neighbours of a cell
// are free (bit d: the neighbour in direction d), the moves it allows (bit d: direction d);
// CostGrid::movesFrom and canMove ask it. The diagonal d sits between the straight directions
// d - 1 and d + 1.
inline unsigned allowedMoves(unsigned free_neighbours, bool allow_corner_cutting) {
  if (allow_corner_cutting) return free_neighbours;
  const unsigned straight = free_neighbours & 0x55u;
  const unsigned from_before = ((straight << 1) | (straight >> 7)) & 0xFFu;  // bit d - 1 moved to d
  const unsigned from_after = ((straight >> 1) | (straight << 7)) & 0xFFu;   // bit d + 1 moved to d
  return straight | (free_neighbours & 0xAAu & from_before & from_after);
}

// Number of 45-degree steps between two move directions: 0 (straight on) .. 4 (reversal).
inline int turnSteps(int from_dir, int to_dir) {
  const int diff = std::abs(from_dir - to_dir);
  return diff <= 4 ? diff : kDirections - diff;
}

// The fewest 45-degree steps of turning any route needs that starts with heading `dir` and
// moves by the offset (dr, dc) in all: the angle from the direction to the offset, rounded up
// to 45 degrees (0 for no offset). Exact, in integers.
inline int turnStepsAtLeast(int dir, int dr, int dc) {
  if (dr == 0 && dc == 0) return 0;
  const long long ux = kDirCol[dir], uy = kDirRow[dir], vx = dc, vy = dr;
  const long long dot = ux * vx + uy * vy, cross = ux * vy - uy * vx;
  const long long uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
  if (cross == 0 && dot > 0) return 0;           // straight on
  if (dot > 0 && 2 * dot * dot >= uu * vv) return 1;   // within 45 degrees: cos >= 1/sqrt 2
  if (dot >= 0) return 2;                        // within 90 degrees
  if (2 * dot * dot <= uu * vv) return 3;        // within 135 degrees: cos >= -1/sqrt 2
  return 4;
}

// The heading change of one 45-degree step, radians: turn_cost (planner/parameters.hpp) prices
// a turn of k steps at turn_cost x k x kTurnStepRadians.
constexpr double kTurnStepRadians = 0.78539816339744830962;  // pi / 4

// A route's heading change: the turns between its consecutive moves, summed, in 45-degree steps
// (the first move turns nothing); -1 when two consecutive cells are not 8-neighbours (not a route).
inline long long routeTurnSteps(const CellPath& route) {
  long long steps = 0;
  int previous = -1;
  for (std::size_t k = 1; k < route.size(); ++k) {
    const int dir = directionBetween(route[k - 1], route[k]);
    if (dir < 0) return -1;
    if (previous >= 0) steps += turnSteps(previous, dir);
    previous = dir;
  }
  return steps;
}

}  // namespace eaci
