#include "maze.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "eaci/random.hpp"
#include "eaci/io/occupancy_map.hpp"

namespace eaci_bench {

namespace {

void fill(std::vector<std::uint8_t>& cells, int size, int top, int left, int height, int width) {
  for (int r = top; r < top + height; ++r)
    for (int c = left; c < left + width; ++c) cells[static_cast<std::size_t>(r) * size + c] = eaci::kFreeValue;
}

}  // namespace

std::vector<std::uint8_t> drawMaze(const MazeLayout& layout, std::uint64_t seed) {
  const int n = layout.size, m = layout.cellsPerSide(), p = layout.pitch(), corridor = layout.corridor;
  if (corridor < 1 || layout.wall < 1 || m < 1) throw std::runtime_error("maze: corridor and wall >= 1 cell, and room for one maze cell");
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(n) * n, eaci::kOccupiedValue);
  eaci::SplitMix64 rng(seed ^ 0xBB67AE8584CAA73BULL);
  std::vector<char> visited(static_cast<std::size_t>(m) * m, 0);
  std::vector<std::pair<int, int>> stack{{0, 0}};
  visited[0] = 1;
  fill(cells, n, 0, 0, corridor, corridor);
  constexpr int kStep[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    int open[4], count = 0;
    for (int d = 0; d < 4; ++d) {
      const int ni = i + kStep[d][0], nj = j + kStep[d][1];
      if (ni >= 0 && ni < m && nj >= 0 && nj < m && !visited[static_cast<std::size_t>(ni) * m + nj]) open[count++] = d;
    }
    if (count == 0) {
      stack.pop_back();
      continue;
    }
    const int d = open[rng.next() % static_cast<std::uint64_t>(count)];
    const int ni = i + kStep[d][0], nj = j + kStep[d][1];
    visited[static_cast<std::size_t>(ni) * m + nj] = 1;
    fill(cells, n, ni * p, nj * p, corridor, corridor);
    // The wall between (i, j) and (ni, nj), opened over the corridor's width.
    if (ni != i) fill(cells, n, std::min(i, ni) * p + corridor, j * p, layout.wall, corridor);
    else fill(cells, n, i * p, std::min(j, nj) * p + corridor, corridor, layout.wall);
    stack.emplace_back(ni, nj);
  }
  return cells;
}

}  // namespace eaci_bench
