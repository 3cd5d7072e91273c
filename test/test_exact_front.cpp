// eaci_bench front's exact Pareto front of route length against total turning
// (src/bench/exact_front.hpp, issue #30): hand-computed cases, and a brute force over every
// simple path on small random maps. The brute force has its own model of the grid (move rule,
// move lengths, turn angles from the move vectors) and derives the front by itself; it shares
// nothing with exactFront but the map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "../src/bench/exact_front.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/random.hpp"
#include "test_support.hpp"

using eaci::Cell;
using eaci::CellPath;
using eaci::CostGrid;
using eaci_bench::FrontPoint;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSqrt2 = 1.41421356237309504880;

// --- The test's own model of the grid -------------------------------------------------------

// Moves as (row, col) steps, in an order of their own: turns come from the angle between them.
const int kStepRow[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
const int kStepCol[8] = {-1, 0, 1, -1, 1, -1, 0, 1};

struct SmallMap {
  std::vector<std::vector<int>> rows;  // 0 free, 1 obstacle; row 0 = top
  bool cutting = false;
  int height() const { return static_cast<int>(rows.size()); }
  int width() const { return static_cast<int>(rows[0].size()); }
  bool free(int r, int c) const { return r >= 0 && c >= 0 && r < height() && c < width() && rows[r][c] == 0; }
  // The move from (r, c) by (dr, dc), both in -1..1 and not both 0: a free target; a diagonal
  // without corner cutting also needs both cells beside it free.
  bool canMove(int r, int c, int dr, int dc) const {
    if (!free(r, c) || !free(r + dr, c + dc)) return false;
    if (dr != 0 && dc != 0 && !cutting) return free(r + dr, c) && free(r, c + dc);
    return true;
  }
  CostGrid grid() const { return CostGrid::fromRows(rows, cutting); }
};

double moveLength(int dr, int dc) { return dr != 0 && dc != 0 ? kSqrt2 : 1.0; }

// The heading change between two moves in 45-degree steps (0..4), from the angle between their
// vectors.
int turnBetween(int dr1, int dc1, int dr2, int dc2) {
  const double dot = dr1 * dr2 + dc1 * dc2;
  const double cross = dr1 * dc2 - dc1 * dr2;
  return static_cast<int>(std::lround(std::atan2(std::abs(cross), dot) / (kPi / 4)));
}

// What the test's model says of a route: "" when it is one (start to goal, every move an allowed
// 8-neighbour move), with its length and total turn; else what is wrong.
std::string measureRoute(const SmallMap& m, const CellPath& route, Cell start, Cell goal, double& length, int& turn) {
  length = 0.0;
  turn = 0;
  if (route.empty()) return "empty";
  if (!(route.front() == start)) return "does not start at the start";
  if (!(route.back() == goal)) return "does not end at the goal";
  int pr = 0, pc = 0;
  for (std::size_t i = 1; i < route.size(); ++i) {
    const int dr = route[i].row - route[i - 1].row, dc = route[i].col - route[i - 1].col;
    if (std::abs(dr) > 1 || std::abs(dc) > 1 || (dr == 0 && dc == 0)) return "jumps at move " + std::to_string(i);
    if (!m.canMove(route[i - 1].row, route[i - 1].col, dr, dc)) return "a move the map does not allow at move " + std::to_string(i);
    length += moveLength(dr, dc);
    if (i > 1) turn += turnBetween(pr, pc, dr, dc);
    pr = dr;
    pc = dc;
  }
  return "";
}

// The shortest length from each cell to the goal, turns ignored, by relaxing every move until
// nothing changes (Bellman-Ford): a lower bound of the length left, for the brute force's cut.
std::vector<double> lengthToGoal(const SmallMap& m, Cell goal) {
  const int w = m.width();
  std::vector<double> to_goal(static_cast<std::size_t>(m.height() * w), kInf);
  to_goal[goal.row * w + goal.col] = 0.0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int r = 0; r < m.height(); ++r)
      for (int c = 0; c < w; ++c)
        for (int k = 0; k < 8; ++k) {
          if (!m.canMove(r, c, kStepRow[k], kStepCol[k])) continue;
          const double via = moveLength(kStepRow[k], kStepCol[k]) + to_goal[(r + kStepRow[k]) * w + c + kStepCol[k]];
          if (via < to_goal[r * w + c]) {
            to_goal[r * w + c] = via;
            changed = true;
          }
        }
  }
  return to_goal;
}

// Brute force: the shortest length of a simple path from start to goal for each total turn
// (index = 45-degree steps, +infinity where no simple path turns exactly that much), by a
// depth-first walk over every simple path (a path ends when it reaches the goal).
//
// Simple paths are enough: all moves have positive length, and cutting a loop out of a route
// (from a cell to its next visit) leaves a route that is strictly shorter and turns no more,
// since the angle between two headings is at most the sum of the angles along any chain of
// headings between them (the triangle inequality on the circle; at the start the cut route's
// first move turns nothing); a route that passes the goal is beaten the same way by its part up
// to the goal. So the shortest route of any turning budget never repeats a cell.
//
// The walk is cut only where it cannot change the front: at a prefix of length L and turn T at
// cell c, every completion has length >= L + lengthToGoal(c) and turn >= T; if a path already
// found has turn <= T and length <= L + lengthToGoal(c), each completion is no better for any
// budget. The cut gives the same minima per budget as the full enumeration.
std::vector<double> shortestByTurn(const SmallMap& m, Cell start, Cell goal, long long& paths_reached, bool cut = true) {
  const int w = m.width();
  const std::vector<double> to_goal = lengthToGoal(m, goal);
  std::vector<char> on_path(static_cast<std::size_t>(m.height() * w), 0);
  std::vector<double> best;  // best[t]: shortest found that turns exactly t steps
  paths_reached = 0;
  const auto dominated = [&](double bound, int turn) {
    for (int t = 0; t <= turn && t < static_cast<int>(best.size()); ++t)
      if (best[t] <= bound) return true;
    return false;
  };
  std::function<void(int, int, int, int, double, int)> walk = [&](int r, int c, int hr, int hc, double length, int turn) {
    if (!std::isfinite(to_goal[r * w + c]) || (cut && dominated(length + to_goal[r * w + c], turn))) return;
    if (r == goal.row && c == goal.col) {
      ++paths_reached;
      if (turn >= static_cast<int>(best.size())) best.resize(turn + 1, kInf);
      if (length < best[turn]) best[turn] = length;
      return;
    }
    for (int k = 0; k < 8; ++k) {
      const int dr = kStepRow[k], dc = kStepCol[k];
      if (!m.canMove(r, c, dr, dc) || on_path[(r + dr) * w + c + dc]) continue;
      on_path[(r + dr) * w + c + dc] = 1;
      const int t = hr == 0 && hc == 0 ? 0 : turnBetween(hr, hc, dr, dc);  // the first move turns nothing
      walk(r + dr, c + dc, dr, dc, length + moveLength(dr, dc), turn + t);
      on_path[(r + dr) * w + c + dc] = 0;
    }
  };
  if (!m.free(start.row, start.col)) return best;
  on_path[start.row * w + start.col] = 1;
  walk(start.row, start.col, 0, 0, 0.0, 0);
  return best;
}

struct ExpectedPoint {
  int turn_steps;
  double length;
};

// The front from the per-turn minima: for k = 0..max_steps the shortest length that turns at most
// k steps, kept where it is strictly shorter (beyond 1e-9, rounding of sums of 1 and sqrt 2) than
// for k - 1.
std::vector<ExpectedPoint> frontOf(const std::vector<double>& by_turn, int max_steps) {
  std::vector<ExpectedPoint> front;
  double at_most_previous = kInf;
  for (int k = 0; k <= max_steps; ++k) {
    double at_most = at_most_previous;
    if (k < static_cast<int>(by_turn.size()) && by_turn[k] < at_most) at_most = by_turn[k];
    if (at_most < at_most_previous - 1e-9) front.push_back({k, at_most});
    at_most_previous = at_most;
  }
  return front;
}

// exactFront's answer against the expected front: the same budgets and lengths, and each route
// one the test's model allows, from start to goal, of the reported length and turn. Returns "" or
// what differs.
std::string compareFront(const SmallMap& m, Cell start, Cell goal, const std::vector<FrontPoint>& got,
                         const std::vector<ExpectedPoint>& expected) {
  std::string defect;
  if (got.size() != expected.size())
    defect += "front has " + std::to_string(got.size()) + " points, expected " + std::to_string(expected.size()) + "; ";
  for (std::size_t i = 0; i < got.size() && i < expected.size(); ++i) {
    const std::string at = "point " + std::to_string(i) + ": ";
    if (got[i].turn_steps != expected[i].turn_steps)
      defect += at + "k " + std::to_string(got[i].turn_steps) + ", expected " + std::to_string(expected[i].turn_steps) + "; ";
    if (std::abs(got[i].length - expected[i].length) > 1e-9)
      defect += at + "length " + std::to_string(got[i].length) + ", expected " + std::to_string(expected[i].length) + "; ";
    double length = 0.0;
    int turn = 0;
    const std::string route = measureRoute(m, got[i].path, start, goal, length, turn);
    if (!route.empty()) {
      defect += at + "route " + route + "; ";
      continue;
    }
    if (std::abs(length - got[i].length) > 1e-9)
      defect += at + "route is " + std::to_string(length) + " long, reported " + std::to_string(got[i].length) + "; ";
    if (turn != got[i].turn_steps)
      defect += at + "route turns " + std::to_string(turn) + " steps, reported " + std::to_string(got[i].turn_steps) + "; ";
  }
  return defect;
}

SmallMap randomMap(std::uint64_t seed, int height, int width, double obstacles, bool cutting) {
  eaci::SplitMix64 random(seed);
  SmallMap m;
  m.cutting = cutting;
  m.rows.assign(height, std::vector<int>(width, 0));
  for (auto& row : m.rows)
    for (int& cell : row) cell = random.uniform() < obstacles ? 1 : 0;
  return m;
}

Cell randomCell(eaci::SplitMix64& random, int height, int width) {
  return Cell{static_cast<int>(random.next() % static_cast<std::uint64_t>(height)),
              static_cast<int>(random.next() % static_cast<std::uint64_t>(width))};
}

// --- Hand-computed fronts ---------------------------------------------------------------------

// An L-shaped corridor, corner cutting forbidden: the only route goes down the left column and
// along the bottom row, length 4, one right angle = 2 steps. Budgets 0 and 1 have no route.
TEST(ExactFront, LShapedCorridorHasOnePointAtTwoSteps) {
  const SmallMap m{{{0, 1, 1},
                    {0, 1, 1},
                    {0, 0, 0}},
                   false};
  const Cell start{0, 0}, goal{2, 2};
  const std::vector<FrontPoint> front = eaci_bench::exactFront(m.grid(), start, goal, 6);
  ASSERT_EQ(front.size(), 1u);
  EXPECT_EQ(front[0].turn_steps, 2);
  EXPECT_NEAR(front[0].length, 4.0, 1e-12);
  EXPECT_EQ(front[0].path, (CellPath{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}}));
  // A budget below the corner: no route at all.
  EXPECT_TRUE(eaci_bench::exactFront(m.grid(), start, goal, 1).empty());
  EXPECT_EQ(eaci_bench::exactFront(m.grid(), start, goal, 2).size(), 1u);
}

// The same corridor with corner cutting: (1,0) -> (2,1) passes the obstacle (1,1) corner to
// corner, down, diagonal, right: 2 + sqrt 2, two 45-degree turns (still 2 steps, and shorter).
TEST(ExactFront, LShapedCorridorWithCornerCuttingTurnsTwoSingleSteps) {
  const SmallMap m{{{0, 1, 1},
                    {0, 1, 1},
                    {0, 0, 0}},
                   true};
  const std::vector<FrontPoint> front = eaci_bench::exactFront(m.grid(), Cell{0, 0}, Cell{2, 2}, 6);
  ASSERT_EQ(front.size(), 1u);
  EXPECT_EQ(front[0].turn_steps, 2);
  EXPECT_NEAR(front[0].length, 2.0 + kSqrt2, 1e-12);
  EXPECT_EQ(front[0].path, (CellPath{{0, 0}, {1, 0}, {2, 1}, {2, 2}}));
}

// An open 3 x 3 grid, corner to corner: the straight diagonal, 2 sqrt 2 with no turn, is both
// the shortest and the least turning route, the whole front.
TEST(ExactFront, OpenSquareCornerToCornerIsOneStraightDiagonal) {
  for (bool cutting : {false, true}) {
    const SmallMap m{{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, cutting};
    const std::vector<FrontPoint> front = eaci_bench::exactFront(m.grid(), Cell{0, 0}, Cell{2, 2}, 8);
    ASSERT_EQ(front.size(), 1u) << "cutting " << cutting;
    EXPECT_EQ(front[0].turn_steps, 0);
    EXPECT_NEAR(front[0].length, 2.0 * kSqrt2, 1e-12);
    EXPECT_EQ(front[0].path, (CellPath{{0, 0}, {1, 1}, {2, 2}}));
  }
}

// Start = goal: the one-cell route, length 0, no turn. A walled-off goal: an empty front.
TEST(ExactFront, StartAtTheGoalAndUnreachableGoal) {
  const SmallMap m{{{0, 1, 0}, {0, 1, 0}, {0, 1, 0}}, true};
  const std::vector<FrontPoint> here = eaci_bench::exactFront(m.grid(), Cell{1, 0}, Cell{1, 0}, 4);
  ASSERT_EQ(here.size(), 1u);
  EXPECT_EQ(here[0].turn_steps, 0);
  EXPECT_EQ(here[0].length, 0.0);
  EXPECT_EQ(here[0].path, (CellPath{{1, 0}}));
  EXPECT_TRUE(eaci_bench::exactFront(m.grid(), Cell{0, 0}, Cell{2, 2}, 8).empty());
}

// --- Against the brute force over simple paths -------------------------------------------------

TEST(ExactFront, MatchesTheBruteForceOverSimplePathsOnSmallRandomMaps) {
  int compared = 0, unreachable = 0, with_trade_off = 0;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    eaci::SplitMix64 random(seed * 7919 + 17);
    const int height = 4 + static_cast<int>(seed % 3);       // 4..6
    const int width = 4 + static_cast<int>((seed / 3) % 3);  // 4..6
    const double obstacles = 0.20 + 0.05 * static_cast<double>(seed % 3);  // 20, 25, 30 %
    const bool cutting = (seed & 1) != 0;
    SmallMap m = randomMap(seed, height, width, obstacles, cutting);
    // Corner to corner for two thirds of the maps (more of them trade length for turning), two
    // random cells (now and then the same) for the rest; start and goal free.
    Cell start{0, 0}, goal{height - 1, width - 1};
    if (seed % 3 == 0) {
      start = randomCell(random, height, width);
      goal = randomCell(random, height, width);
    }
    m.rows[start.row][start.col] = 0;
    m.rows[goal.row][goal.col] = 0;
    const CostGrid grid = m.grid();
    const std::string where = "seed " + std::to_string(seed) + " (" + std::to_string(height) + "x" +
                              std::to_string(width) + (cutting ? ", corner cutting" : "") + ")";

    long long paths = 0;
    const std::vector<double> by_turn = shortestByTurn(m, start, goal, paths);
    // Budgets up to the most turning path the walk reached and two steps beyond (nothing may
    // appear there); where the front has two points or more, again with the budget cut just
    // below its last (shortest) point.
    const int max_steps = static_cast<int>(by_turn.size()) + 2;
    const std::vector<ExpectedPoint> expected = frontOf(by_turn, max_steps);
    const std::vector<FrontPoint> got = eaci_bench::exactFront(grid, start, goal, max_steps);
    EXPECT_EQ(compareFront(m, start, goal, got, expected), "") << where;
    for (const FrontPoint& p : got) EXPECT_EQ(eaci::test::routeDefect(grid, p.path, start, goal), "") << where;
    ++compared;
    if (expected.empty()) ++unreachable;
    if (expected.size() >= 2) {
      ++with_trade_off;
      const int cut = expected[expected.size() - 2].turn_steps;  // drops the last (shortest) point
      EXPECT_EQ(compareFront(m, start, goal, eaci_bench::exactFront(grid, start, goal, cut), frontOf(by_turn, cut)), "")
          << where << " max_steps " << cut;
    }
  }
  EXPECT_EQ(compared, 2000);
  EXPECT_GT(unreachable, 100);    // walled-off goals occur
  EXPECT_GT(with_trade_off, 30);  // fronts of two points or more: the trade between length and turns
}

// On 4 x 4 maps (at most ~10^5 simple paths) the brute force without its cut: every simple path
// from corner to corner. The cut walk gives the same front, and so does exactFront.
TEST(ExactFront, MatchesTheUncutEnumerationOfEverySimplePathOn4x4Maps) {
  int with_trade_off = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    SmallMap m = randomMap(seed + 100000, 4, 4, 0.2 + 0.05 * static_cast<double>(seed % 3), (seed & 1) != 0);
    const Cell start{0, 0}, goal{3, 3};
    m.rows[0][0] = m.rows[3][3] = 0;
    long long cut_paths = 0, all_paths = 0;
    const std::vector<double> cut = shortestByTurn(m, start, goal, cut_paths, true);
    const std::vector<double> all = shortestByTurn(m, start, goal, all_paths, false);
    EXPECT_LE(cut_paths, all_paths);
    const int max_steps = static_cast<int>(all.size()) + 2;
    const std::vector<ExpectedPoint> expected = frontOf(all, max_steps), from_cut = frontOf(cut, max_steps);
    ASSERT_EQ(from_cut.size(), expected.size()) << "seed " << seed;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      EXPECT_EQ(from_cut[i].turn_steps, expected[i].turn_steps) << "seed " << seed;
      EXPECT_NEAR(from_cut[i].length, expected[i].length, 1e-9) << "seed " << seed;
    }
    EXPECT_EQ(compareFront(m, start, goal, eaci_bench::exactFront(m.grid(), start, goal, max_steps), expected), "")
        << "seed " << seed;
    if (expected.size() >= 2) ++with_trade_off;
  }
  EXPECT_GE(with_trade_off, 3);  // 5 of the 200
}

}  // namespace
