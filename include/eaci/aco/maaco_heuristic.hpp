// MAACO's heuristic (re-implemented from public descriptions, not the authors' code):
// eta_j = 1 / (g d_sj + h d_jT + a c_j), h = wh_max - (wh_max - wh_min) exp(-k_h d_jT / d_ST),
// g = 1 - h, c_j = 1 when the move turns (0 straight on and on the first move).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/moves.hpp"

namespace eaci {

inline double straightDistance(Cell a, Cell b) { return std::hypot(a.row - b.row, a.col - b.col); }

// h, the weight of the distance still to go: wh_min at the goal, toward wh_max far from it.
inline double goalDistanceWeight(double d_jt, double d_st, double wh_max, double wh_min, double k_h) {
  return wh_max - (wh_max - wh_min) * std::exp(-k_h * d_jt / d_st);
}

struct MaacoHeuristicWeights {
  double wh_max = 0.9;
  double wh_min = 0.2;
  double k_h = 1.0;
  double turn_weight = 1.0;  // a
};

// 1 / eta_j: g d_sj + h d_jT + a c_j.
inline double maacoHeuristicDistance(double d_sj, double d_jt, double d_st, bool turns, const MaacoHeuristicWeights& w) {
  const double h = goalDistanceWeight(d_jt, d_st, w.wh_max, w.wh_min, w.k_h);
  return (1.0 - h) * d_sj + h * d_jt + w.turn_weight * (turns ? 1.0 : 0.0);
}

// The heuristic rule of the walk (ant_walk.hpp): 1 / eta for the move `dir` from `here`.
// d_sj: the length the ant has walked to j (walked_to_here + the step), or the straight line S -> j.
struct MaacoHeuristic {
  MaacoHeuristicWeights weights;
  bool straight_start_distance = false;
  Cell start, goal;
  double d_st = 1.0;

  MaacoHeuristic() = default;
  MaacoHeuristic(const MaacoHeuristicWeights& w, bool straight, Cell s, Cell e)
      : weights(w), straight_start_distance(straight), start(s), goal(e), d_st(straightDistance(s, e)) {}

  template <class Setup>
  double operator()(const Setup& /*setup*/, double walked_to_here, Cell here, std::uint32_t /*next*/,
                    std::size_t /*target*/, int previous_dir, int dir) const {
    const Cell j = step(here, dir);
    const double d_sj = straight_start_distance ? straightDistance(start, j) : walked_to_here + stepLength(dir);
    const bool turns = previous_dir >= 0 && previous_dir != dir;
    return maacoHeuristicDistance(d_sj, straightDistance(j, goal), d_st, turns, weights);
  }
};

}  // namespace eaci
