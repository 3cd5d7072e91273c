#include "exact_front.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "eaci/grid/moves.hpp"

namespace eaci_bench {

// What it computes: exact_front.hpp. A Dijkstra over the states (cell, incoming direction or
// none at the start, steps turned so far), max_steps + 1 layers of them; the goal's states are
// not expanded (a route ends there). Layer k at the goal holds the shortest route that turns by
// exactly k steps; the front keeps it where it beats every smaller k.
std::vector<FrontPoint> exactFront(const eaci::CostGrid& grid, eaci::Cell start, eaci::Cell goal, int max_steps) {
  const std::size_t cells = grid.cellCount();
  const std::size_t headings = eaci::kDirections + 1;  // 8 = no heading yet (the start)
  const std::size_t layers = static_cast<std::size_t>(max_steps) + 1;
  const auto id = [&](std::size_t cell, std::size_t h, std::size_t k) { return (k * headings + h) * cells + cell; };
  const std::size_t n = cells * headings * layers;
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> back(n, -1);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  const std::size_t s = id(grid.index(start), eaci::kDirections, 0);
  dist[s] = 0.0;
  open.push({0.0, s});
  const auto cellOf = [&](std::size_t index) {
    return eaci::Cell{static_cast<int>(index / static_cast<std::size_t>(grid.width())),
                      static_cast<int>(index % static_cast<std::size_t>(grid.width()))};
  };
  while (!open.empty()) {
    const auto [d, state] = open.top();
    open.pop();
    if (d > dist[state]) continue;
    const std::size_t cell = state % cells, h = (state / cells) % headings, k = state / cells / headings;
    const eaci::Cell c = cellOf(cell);
    if (c == goal) continue;  // a route ends at the goal
    const unsigned moves = grid.movesFrom(c);
    for (int dir = 0; dir < eaci::kDirections; ++dir) {
      if (((moves >> dir) & 1u) == 0) continue;
      const std::size_t k2 = k + (h == eaci::kDirections ? 0 : static_cast<std::size_t>(eaci::turnSteps(static_cast<int>(h), dir)));
      if (k2 >= layers) continue;
      const std::size_t next = id(grid.index(eaci::step(c, dir)), static_cast<std::size_t>(dir), k2);
      const double nd = d + eaci::stepLength(dir);
      if (nd < dist[next]) {
        dist[next] = nd;
        back[next] = static_cast<std::int64_t>(state);
        open.push({nd, next});
      }
    }
  }
  std::vector<FrontPoint> front;
  double best_so_far = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < layers; ++k) {
    std::size_t best = n;
    for (std::size_t h = 0; h < headings; ++h) {
      const std::size_t state = id(grid.index(goal), h, k);
      if (best == n || dist[state] < dist[best]) best = state;
    }
    // Strictly shorter than every route that turns less (1e-9: sums of 1 and sqrt 2 in other orders).
    if (!(dist[best] < best_so_far - 1e-9)) continue;
    best_so_far = dist[best];
    FrontPoint p{static_cast<int>(k), dist[best], {}};
    for (std::int64_t x = static_cast<std::int64_t>(best); x >= 0; x = back[static_cast<std::size_t>(x)])
      p.path.push_back(cellOf(static_cast<std::size_t>(x) % cells));
    std::reverse(p.path.begin(), p.path.end());
    front.push_back(std::move(p));
  }
  return front;
}

}  // namespace eaci_bench
