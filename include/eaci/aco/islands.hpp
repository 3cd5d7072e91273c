// Island selection (Eq. 13-15): waypoints L_1 = S, L_2, ..., L_N = E that every ant visits in order.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/stop_poll.hpp"

namespace eaci {

inline double euclidean(Cell a, Cell b) { return std::hypot(a.row - b.row, a.col - b.col); }

// Eq. 13: radius of the search circle, r_s = d_SE / (N - 1).
inline double searchRadius(Cell start, Cell goal, int island_count) {
  return euclidean(start, goal) / static_cast<double>(island_count - 1);
}

// Eq. 14: D_I = |I - S| + |I - E|.
inline double islandScore(Cell candidate, Cell start, Cell goal) {
  return euclidean(candidate, start) + euclidean(candidate, goal);
}

// Eq. 13-15 with the gaps of the paper closed (spec 3.2):
// - candidates are cells free on the auxiliary map, reachable from S on the original
//   map (`reachable`), within r_s of the current island and strictly closer to E than
//   it, so every step advances and the loop ends on every map;
// - the smallest D_I wins; ties go to the candidate nearest E, then to the lower serial number;
// - the search stops when E lies inside the circle of the current island (then L_N = E)
//   or when no candidate is left (E follows directly; the ants then walk that leg).
// Returns S, the islands, E. The count can exceed N where the straight line is blocked.
// `stop`: ticked once per row of candidates; stopped, the islands are unfinished (the caller
// reads stop->stopped()).
inline std::vector<Cell> paperIslands(const CostGrid& auxiliary, const std::vector<std::uint8_t>& reachable,
                                      Cell start, Cell goal, int island_count, StopPoll* stop = nullptr) {
  constexpr double kTolerance = 1e-9;
  std::vector<Cell> islands{start};
  if (start == goal) return islands;
  const double radius = searchRadius(start, goal, island_count);
  const int reach = static_cast<int>(std::floor(radius + kTolerance));
  Cell current = start;
  while (euclidean(current, goal) > radius + kTolerance) {
    const double current_to_goal = euclidean(current, goal);
    Cell best{-1, -1};
    double best_score = std::numeric_limits<double>::infinity();
    double best_to_goal = std::numeric_limits<double>::infinity();
    for (int r = current.row - reach; r <= current.row + reach; ++r) {
      if (stop != nullptr && stop->tick(2 * static_cast<std::size_t>(reach) + 1)) return islands;
      for (int c = current.col - reach; c <= current.col + reach; ++c) {
        const Cell candidate{r, c};
        if (!auxiliary.isFree(candidate) || !reachable[auxiliary.index(candidate)]) continue;
        if (euclidean(candidate, current) > radius + kTolerance) continue;
        const double to_goal = euclidean(candidate, goal);
        if (to_goal >= current_to_goal - kTolerance) continue;
        const double score = islandScore(candidate, start, goal);
        // Row-major scan order already prefers the lower serial number on a full tie.
        if (score < best_score - kTolerance ||
            (score < best_score + kTolerance && to_goal < best_to_goal - kTolerance)) {
          best = candidate;
          best_score = score;
          best_to_goal = to_goal;
        }
      }
    }
    if (best.row < 0) break;
    islands.push_back(best);
    current = best;
  }
  islands.push_back(goal);
  return islands;
}

}  // namespace eaci
