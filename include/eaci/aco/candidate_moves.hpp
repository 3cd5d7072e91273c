// Candidate moves: which of an ant's open moves (free, in the region, off its taboo list, onto
// no island but the leg's) its transition rule chooses among. A rule maps the open moves
// (bit d: direction d) to the candidates; an ant left with none is lost.
#pragma once

#include "eaci/grid/cell.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

// Classic ACO and EACI (Eq. 8): every open move is a candidate.
struct AllowedMoves {
  static constexpr bool kEveryOpenMove = true;  // the walk takes them as it finds them
  unsigned operator()(unsigned open, Cell /*here*/) const { return open; }
};

// The moves that go against neither sign of (d_row, d_col): no step up when the way is down, ...
inline unsigned movesNotAgainst(int d_row, int d_col) {
  unsigned mask = 0;
  for (int d = 0; d < kDirections; ++d) {
    const bool against_row = (d_row > 0 && kDirRow[d] < 0) || (d_row < 0 && kDirRow[d] > 0);
    const bool against_col = (d_col > 0 && kDirCol[d] < 0) || (d_col < 0 && kDirCol[d] > 0);
    if (!against_row && !against_col) mask |= 1u << d;
  }
  return mask;
}

// The direction of the move that points from `from` toward `to` to the nearest 45 degrees
// (the signs of the row and column differences); -1 when they are the same cell.
inline int octantToward(Cell from, Cell to) {
  const int d_row = (to.row > from.row) - (to.row < from.row);
  const int d_col = (to.col > from.col) - (to.col < from.col);
  return directionBetween(from, Cell{from.row + d_row, from.col + d_col});
}

// The `keep` open moves that turn least away from direction `toward`, ties to the lower direction.
inline unsigned movesNearestInAngle(unsigned open, int toward, int keep) {
  unsigned kept = 0;
  for (int turn = 0; turn <= 4 && keep > 0; ++turn)
    for (int d = 0; d < kDirections && keep > 0; ++d)
      if ((open & (1u << d)) && turnSteps(toward, d) == turn) {
        kept |= 1u << d;
        --keep;
      }
  return kept;
}

// MAACO's goal-direction filter (docs/algorithm.md, MAACO, choices 4 and 5).
// kQuadrant: the moves against neither sign of S -> E; none left: against neither sign of
// here -> E; none left: every open move. kNearest3: the three open moves nearest in angle to
// here -> E (to the nearest 45 degrees); fewer when fewer are open.
struct GoalDirectionMoves {
  static constexpr bool kEveryOpenMove = false;
  bool nearest_three = false;
  Cell goal;
  unsigned start_to_goal = 0xFFu;  // movesNotAgainst(S -> E)

  GoalDirectionMoves() = default;
  GoalDirectionMoves(bool nearest3, Cell start, Cell goal_cell)
      : nearest_three(nearest3), goal(goal_cell),
        start_to_goal(movesNotAgainst(goal_cell.row - start.row, goal_cell.col - start.col)) {}

  unsigned operator()(unsigned open, Cell here) const {
    if (nearest_three) return movesNearestInAngle(open, octantToward(here, goal), 3);
    if (const unsigned along_start = open & start_to_goal) return along_start;
    if (const unsigned along_here = open & movesNotAgainst(goal.row - here.row, goal.col - here.col)) return along_here;
    return open;
  }
};

}  // namespace eaci
