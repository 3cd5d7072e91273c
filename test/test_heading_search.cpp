// The exact reference of the combined objective (issue #30): cost + turn_cost x heading change.
// Expectations come from hand computation, from a brute force over simple paths, and from a
// plain Dijkstra over an explicitly built (cell, heading) graph; both are written here,
// independently of the library (their own move rule, move costs and turn angles).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <vector>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/planner.hpp"
#include "eaci/random.hpp"
#include "eaci/search/astar.hpp"
#include "eaci/search/heading_search.hpp"
#include "test_support.hpp"

using eaci::Cell;
using eaci::CellPath;
using eaci::CostGrid;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

// --- The test's own model of the grid -------------------------------------------------------

// Directions as (row, col) steps; any order will do here: turns come from the angle itself.
const int kStepRow[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
const int kStepCol[8] = {-1, 0, 1, -1, 1, -1, 0, 1};

struct TestMap {
  int rows = 0, cols = 0;
  bool cutting = false;
  std::vector<int> cost;  // per cell: -1 obstacle, else 0..252
  bool free(int r, int c) const { return r >= 0 && c >= 0 && r < rows && c < cols && cost[r * cols + c] >= 0; }
  // The move from (r, c) by direction k, if allowed: free target; a diagonal without corner
  // cutting also needs both cells beside it free.
  bool canMove(int r, int c, int k) const {
    const int dr = kStepRow[k], dc = kStepCol[k];
    if (!free(r + dr, c + dc)) return false;
    if (dr != 0 && dc != 0 && !cutting) return free(r + dr, c) && free(r, c + dc);
    return true;
  }
  // global_planner's rule with neutral 50, factor 3: length x (50 + 3 c) / 50 of the entered cell.
  double moveCost(int r, int c, int k) const {
    const double length = kStepRow[k] != 0 && kStepCol[k] != 0 ? std::sqrt(2.0) : 1.0;
    return length * (50.0 + 3.0 * cost[(r + kStepRow[k]) * cols + c + kStepCol[k]]) / 50.0;
  }
  CostGrid grid() const {
    CostGrid g(cols, rows, cutting);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        if (cost[r * cols + c] < 0) g.setBlocked(Cell{r, c}, true);
        else g.setCost(Cell{r, c}, static_cast<std::uint8_t>(cost[r * cols + c]));
      }
    return g;
  }
};

// The angle between two directions, radians, from their vectors.
double turnAngle(int a, int b) {
  const double dot = kStepRow[a] * kStepRow[b] + kStepCol[a] * kStepCol[b];
  const double cross = kStepRow[a] * kStepCol[b] - kStepCol[a] * kStepRow[b];
  return std::atan2(std::abs(cross), dot);
}

// The angle between a heading (radians counter-clockwise from east, north being row - 1) and
// direction k, radians, from their vectors; 0 for no heading (NaN).
double endTurn(double yaw, int k) {
  if (std::isnan(yaw)) return 0.0;
  const double x = std::cos(yaw), y = std::sin(yaw);  // y up: against the rows
  const double kx = kStepCol[k], ky = -kStepRow[k];
  return std::atan2(std::abs(x * ky - y * kx), x * kx + y * ky);
}

// The combined cost of a route in the test's own terms; +infinity for a move it does not allow.
double testCombinedCost(const TestMap& m, const CellPath& route, double turn_cost, double start_yaw = NAN,
                        double goal_yaw = NAN) {
  double total = 0.0;
  int previous = -1;
  for (std::size_t i = 1; i < route.size(); ++i) {
    int k = 0;
    while (k < 8 && !(route[i].row - route[i - 1].row == kStepRow[k] && route[i].col - route[i - 1].col == kStepCol[k])) ++k;
    if (k == 8 || !m.canMove(route[i - 1].row, route[i - 1].col, k)) return kInf;
    total += m.moveCost(route[i - 1].row, route[i - 1].col, k);
    total += turn_cost * (previous >= 0 ? turnAngle(previous, k) : endTurn(start_yaw, k));
    previous = k;
  }
  if (previous >= 0) total += turn_cost * endTurn(goal_yaw, previous);
  return total;
}

// The cheapest cost from each cell to the goal without turns, by relaxing every move until
// nothing changes (Bellman-Ford): a lower bound of the combined cost left.
std::vector<double> costToGoal(const TestMap& m, Cell goal) {
  std::vector<double> to_goal(m.rows * m.cols, kInf);
  to_goal[goal.row * m.cols + goal.col] = 0.0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int r = 0; r < m.rows; ++r)
      for (int c = 0; c < m.cols; ++c)
        for (int k = 0; k < 8; ++k) {
          if (!m.free(r, c) || !m.canMove(r, c, k)) continue;
          const double via = m.moveCost(r, c, k) + to_goal[(r + kStepRow[k]) * m.cols + c + kStepCol[k]];
          if (via < to_goal[r * m.cols + c]) {
            to_goal[r * m.cols + c] = via;
            changed = true;
          }
        }
  }
  return to_goal;
}

// Brute force: every simple path from start to goal, depth first, cut only where its cost so
// far plus the cost left without turns (costToGoal) cannot beat the best found.
// With headings at the ends (NaN: none), the first move also pays its turn from the start
// heading and the last its turn onto the goal heading.
double bruteForce(const TestMap& m, Cell start, Cell goal, double turn_cost, double start_yaw = NAN,
                  double goal_yaw = NAN) {
  const std::vector<double> to_goal = costToGoal(m, goal);
  std::vector<char> on_path(m.rows * m.cols, 0);
  double best = kInf;
  std::function<void(int, int, int, double)> walk = [&](int r, int c, int heading, double cost) {
    if (cost + to_goal[r * m.cols + c] >= best + 1e-12) return;
    if (r == goal.row && c == goal.col) {
      best = std::min(best, cost + (heading >= 0 ? turn_cost * endTurn(goal_yaw, heading) : 0.0));
      return;
    }
    for (int k = 0; k < 8; ++k) {
      const int nr = r + kStepRow[k], nc = c + kStepCol[k];
      if (!m.canMove(r, c, k) || on_path[nr * m.cols + nc]) continue;
      on_path[nr * m.cols + nc] = 1;
      walk(nr, nc, k,
           cost + m.moveCost(r, c, k) + turn_cost * (heading >= 0 ? turnAngle(heading, k) : endTurn(start_yaw, k)));
      on_path[nr * m.cols + nc] = 0;
    }
  };
  on_path[start.row * m.cols + start.col] = 1;
  walk(start.row, start.col, -1, 0.0);
  return best;
}

// Dijkstra over a graph built first: node (cell, heading), heading 8 = the start's, none.
double stateGraphDijkstra(const TestMap& m, Cell start, Cell goal, double turn_cost) {
  const int n = m.rows * m.cols * 9;
  std::vector<std::vector<std::pair<int, double>>> edges(n);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c)
      for (int h = 0; h < 9; ++h)
        for (int k = 0; k < 8; ++k) {
          if (!m.free(r, c) || !m.canMove(r, c, k)) continue;
          const int to = ((r + kStepRow[k]) * m.cols + c + kStepCol[k]) * 9 + k;
          edges[(r * m.cols + c) * 9 + h].push_back({to, m.moveCost(r, c, k) + (h < 8 ? turn_cost * turnAngle(h, k) : 0.0)});
        }
  std::vector<double> dist(n, kInf);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  const int source = (start.row * m.cols + start.col) * 9 + 8;
  dist[source] = 0.0;
  open.push({0.0, source});
  while (!open.empty()) {
    const auto [d, v] = open.top();
    open.pop();
    if (d > dist[v]) continue;
    for (const auto& [to, w] : edges[v])
      if (d + w < dist[to]) {
        dist[to] = d + w;
        open.push({dist[to], to});
      }
  }
  double best = start == goal ? 0.0 : kInf;
  for (int h = 0; h < 8; ++h) best = std::min(best, dist[(goal.row * m.cols + goal.col) * 9 + h]);
  return best;
}

TestMap randomMap(std::uint64_t seed, int rows, int cols, double obstacles, bool with_costs) {
  eaci::SplitMix64 random(seed);
  TestMap m;
  m.rows = rows;
  m.cols = cols;
  m.cutting = (seed & 1) != 0;
  m.cost.assign(rows * cols, 0);
  for (int& c : m.cost) {
    if (random.uniform() < obstacles) c = -1;
    else if (with_costs && random.uniform() < 0.4) c = static_cast<int>(random.uniform() * 253);
  }
  m.cost[0] = 0;                   // start: top left
  m.cost[rows * cols - 1] = 0;     // goal: bottom right
  return m;
}

TestMap fromRows(const std::vector<std::vector<int>>& rows, bool cutting) {
  TestMap m;
  m.rows = static_cast<int>(rows.size());
  m.cols = static_cast<int>(rows[0].size());
  m.cutting = cutting;
  for (const auto& row : rows)
    for (int v : row) m.cost.push_back(v != 0 ? -1 : 0);
  return m;
}

// size x size open cells, the goal in the bottom right corner walled in by its three neighbours.
CostGrid walledInGoal(int size) {
  CostGrid grid = CostGrid::fromRows(std::vector<std::vector<int>>(size, std::vector<int>(size, 0)), false);
  for (const Cell c : {Cell{size - 2, size - 2}, Cell{size - 2, size - 1}, Cell{size - 1, size - 2}}) grid.setBlocked(c, true);
  return grid;
}

}  // namespace

// --- Hand-computed cases ---------------------------------------------------------------------

TEST(HeadingSearch, StraightCorridorHasNoTurn) {
  // A corridor running north to south: the first move turns nothing, whatever the heading
  // the search starts from, and the route goes straight: combined cost = length = 5.
  const CostGrid grid = CostGrid::fromRows({{1, 0, 1}, {1, 0, 1}, {1, 0, 1}, {1, 0, 1}, {1, 0, 1}, {1, 0, 1}}, false);
  for (double turn_cost : {0.0, 0.5, 7.0}) {
    const eaci::TurningPath p = eaci::cheapestTurningPath(grid, Cell{0, 1}, Cell{5, 1}, turn_cost);
    ASSERT_TRUE(p.found);
    EXPECT_EQ(p.turn_steps, 0);
    EXPECT_DOUBLE_EQ(p.combined_cost, 5.0);
    EXPECT_DOUBLE_EQ(p.cost, 5.0);
    EXPECT_EQ(p.path.size(), 6u);
  }
}

TEST(HeadingSearch, AnLGivesExactlyOneRightAngle) {
  // Right along the top row, then down the last column: 8 moves and one 90-degree turn.
  const CostGrid grid = CostGrid::fromRows(
      {{0, 0, 0, 0, 0}, {1, 1, 1, 1, 0}, {1, 1, 1, 1, 0}, {1, 1, 1, 1, 0}, {1, 1, 1, 1, 0}}, false);
  for (double turn_cost : {0.25, 1.0, 4.0}) {
    const eaci::TurningPath p = eaci::cheapestTurningPath(grid, Cell{0, 0}, Cell{4, 4}, turn_cost);
    ASSERT_TRUE(p.found);
    EXPECT_EQ(p.turn_steps, 2);  // two 45-degree steps
    EXPECT_NEAR(p.combined_cost, 8.0 + turn_cost * kPi / 2, 1e-12);
    EXPECT_DOUBLE_EQ(p.cost, 8.0);
    EXPECT_EQ(p.path.size(), 9u);
  }
}

TEST(HeadingSearch, AmongTheShortestRoutesTakesTheOneThatTurnsLeast) {
  // Past the obstacle at (1, 3), no corner cutting. Every shortest route is 4 + 2 sqrt 2 long;
  // stepping up at once and down at the end turns 45 + 45 degrees, stepping up and back down
  // beside the obstacle turns 4 x 45. No route turns less than 90 degrees: it has to leave the
  // start's row and come back to it.
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0, 0, 0, 0, 0}, {0, 0, 0, 1, 0, 0, 0}, {0, 0, 0, 0, 0, 0, 0}}, false);
  const double shortest = 4.0 + 2.0 * std::sqrt(2.0);
  ASSERT_NEAR(eaci::cheapestPath(grid, Cell{1, 0}, Cell{1, 6}).cost, shortest, 1e-12);
  for (double turn_cost : {0.01, 1.0}) {
    const eaci::TurningPath p = eaci::cheapestTurningPath(grid, Cell{1, 0}, Cell{1, 6}, turn_cost);
    ASSERT_TRUE(p.found);
    EXPECT_NEAR(p.cost, shortest, 1e-12);
    EXPECT_EQ(p.turn_steps, 2);
    EXPECT_NEAR(p.combined_cost, shortest + turn_cost * kPi / 2, 1e-12);
  }
}

TEST(HeadingSearch, ADearTurnBuysADearerRoute) {
  // Row 0 from S to G runs through three cells of cost 50 (a move into one costs 4 x its
  // length under neutral 50, factor 3): straight on costs 4 + 4 + 4 + 1 = 13 and turns nothing.
  // Round them through row 1 (SE, E, E, NE) costs 2 + 2 sqrt 2 and turns 45 + 45 degrees; every
  // way off row 0 and back turns at least 90 degrees. So the optimum is
  // min(13, 2 + 2 sqrt 2 + turn_cost x pi/2): round below turn_cost 5.2, straight above.
  TestMap m = fromRows({{0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}}, false);
  for (int c = 1; c <= 3; ++c) m.cost[c] = 50;
  const CostGrid grid = m.grid();
  const double round = 2.0 + 2.0 * std::sqrt(2.0);
  const eaci::TurningPath cheap = eaci::cheapestTurningPath(grid, Cell{0, 0}, Cell{0, 4}, 1.0);
  ASSERT_TRUE(cheap.found);
  EXPECT_NEAR(cheap.cost, round, 1e-12);
  EXPECT_EQ(cheap.turn_steps, 2);
  EXPECT_NEAR(cheap.combined_cost, round + kPi / 2, 1e-12);
  const eaci::TurningPath dear = eaci::cheapestTurningPath(grid, Cell{0, 0}, Cell{0, 4}, 10.0);
  ASSERT_TRUE(dear.found);
  EXPECT_NEAR(dear.cost, 13.0, 1e-12);
  EXPECT_EQ(dear.turn_steps, 0);
  EXPECT_NEAR(dear.combined_cost, 13.0, 1e-12);
  EXPECT_EQ(dear.path, (CellPath{{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}}));
}

TEST(HeadingSearch, UnreachableOrBlockedEndsGiveNoRoute) {
  const CostGrid grid = CostGrid::fromRows({{0, 1, 0}, {0, 1, 0}, {0, 1, 0}}, true);
  EXPECT_FALSE(eaci::cheapestTurningPath(grid, Cell{0, 0}, Cell{0, 2}, 1.0).found);
  EXPECT_FALSE(eaci::cheapestTurningPath(grid, Cell{0, 0}, Cell{0, 1}, 1.0).found);
  EXPECT_FALSE(eaci::cheapestTurningPath(grid, Cell{0, 0}, Cell{5, 5}, 1.0).found);
  const eaci::TurningPath here = eaci::cheapestTurningPath(grid, Cell{2, 0}, Cell{2, 0}, 1.0);
  ASSERT_TRUE(here.found);
  EXPECT_EQ(here.path.size(), 1u);
  EXPECT_EQ(here.combined_cost, 0.0);
}

// --- Against the brute force and the explicit state graph ------------------------------------

TEST(HeadingSearch, MatchesTheBruteForceOverSimplePathsOnSmallRandomMaps) {
  int compared = 0, longer_for_fewer_turns = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const int size = 5 + static_cast<int>(seed % 3);  // 5 x 5 to 7 x 7
    const TestMap m = randomMap(seed, size, size, 0.25, seed % 4 >= 2);
    const CostGrid grid = m.grid();
    const Cell start{0, 0}, goal{size - 1, size - 1};
    const double shortest = bruteForce(m, start, goal, 0.0);
    for (double turn_cost : {0.0, 0.05, 0.4, 1.5, 6.0}) {
      const double expected = bruteForce(m, start, goal, turn_cost);
      const eaci::TurningPath p = eaci::cheapestTurningPath(grid, start, goal, turn_cost);
      ASSERT_EQ(p.found, std::isfinite(expected)) << "seed " << seed;
      if (!p.found) continue;
      ++compared;
      EXPECT_NEAR(p.combined_cost, expected, 1e-9) << "seed " << seed << " turn_cost " << turn_cost;
      // The route is one the test's own model allows and prices the same.
      EXPECT_NEAR(testCombinedCost(m, p.path, turn_cost), p.combined_cost, 1e-9) << "seed " << seed;
      EXPECT_EQ(eaci::test::routeDefect(grid, p.path, start, goal), "") << "seed " << seed;
      if (p.cost > shortest + 1e-9) ++longer_for_fewer_turns;
    }
  }
  EXPECT_GT(compared, 150);
  EXPECT_GT(longer_for_fewer_turns, 5);  // the maps do exercise the trade between length and turns
}

TEST(HeadingSearch, MatchesADijkstraOverTheExplicitStateGraph) {
  int compared = 0;
  for (std::uint64_t seed = 100; seed < 160; ++seed) {
    const int rows = 5 + static_cast<int>(seed % 5), cols = 5 + static_cast<int>((seed / 5) % 5);  // 5..9
    const TestMap m = randomMap(seed, rows, cols, 0.3, seed % 3 == 0);
    const CostGrid grid = m.grid();
    const Cell start{0, 0}, goal{rows - 1, cols - 1};
    eaci::HeadingSearch search;  // one search object for all: kept buffers must not leak into results
    for (double turn_cost : {0.0, 0.1, 1.0, 3.0}) {
      const double expected = stateGraphDijkstra(m, start, goal, turn_cost);
      const eaci::TurningPath p = search.cheapestPath(grid, start, goal, turn_cost);
      ASSERT_EQ(p.found, std::isfinite(expected)) << "seed " << seed;
      if (!p.found) continue;
      ++compared;
      EXPECT_NEAR(p.combined_cost, expected, 1e-9) << "seed " << seed << " turn_cost " << turn_cost;
      EXPECT_NEAR(testCombinedCost(m, p.path, turn_cost), expected, 1e-9) << "seed " << seed;
    }
  }
  EXPECT_GT(compared, 150);
}

TEST(HeadingSearch, EndHeadingsMatchTheBruteForceOnSmallRandomMaps) {
  // Random headings at both ends, or at one: the brute force prices the first move's turn from
  // the start heading and the last move's onto the goal heading with its own angles.
  eaci::SplitMix64 headings(7);
  int compared = 0, other_route = 0;
  for (std::uint64_t seed = 300; seed < 360; ++seed) {
    const int size = 5 + static_cast<int>(seed % 3);
    const TestMap m = randomMap(seed, size, size, 0.2, seed % 4 >= 2);
    const CostGrid grid = m.grid();
    const Cell start{0, 0}, goal{size - 1, size - 1};
    eaci::HeadingSearch search;
    for (double turn_cost : {0.1, 1.0, 4.0}) {
      eaci::EndHeadings ends;
      ends.start = seed % 3 == 2 ? NAN : (headings.uniform() * 4 - 2) * kPi;
      ends.goal = seed % 3 == 1 ? NAN : (headings.uniform() * 4 - 2) * kPi;
      const double expected = bruteForce(m, start, goal, turn_cost, ends.start, ends.goal);
      const eaci::TurningPath p = search.cheapestPath(grid, start, goal, turn_cost, nullptr, ends);
      ASSERT_EQ(p.found, std::isfinite(expected)) << "seed " << seed;
      if (!p.found) continue;
      ++compared;
      EXPECT_NEAR(p.combined_cost, expected, 1e-9) << "seed " << seed << " turn_cost " << turn_cost;
      EXPECT_NEAR(testCombinedCost(m, p.path, turn_cost, ends.start, ends.goal), expected, 1e-9) << "seed " << seed;
      EXPECT_EQ(eaci::test::routeDefect(grid, p.path, start, goal), "") << "seed " << seed;
      if (p.path != search.cheapestPath(grid, start, goal, turn_cost).path) ++other_route;
    }
  }
  EXPECT_GT(compared, 120);
  EXPECT_GT(other_route, 10);  // the headings do change routes
}

TEST(HeadingSearch, TheGoalHeadingPicksTheLastLegAndTheStartHeadingTheFirst) {
  // 3 x 5 open cells, S bottom left, G top right: every shortest route is two north-east moves
  // and two east moves (2 + 2 sqrt 2 long), and the two that turn once (45
  // degrees) are NE NE E E and E E NE NE. Entering G heading east (goal yaw 0), the first ends
  // lined up and pays nothing more; the second pays a further 45 degrees. A goal yaw of 45
  // degrees picks the second; a start yaw of 45 degrees (no goal yaw) the first.
  const CostGrid grid = CostGrid::fromRows({{0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}}, false);
  const Cell start{2, 0}, goal{0, 4};
  const double shortest = 2.0 + 2.0 * std::sqrt(2.0);
  const CellPath diagonal_first{{2, 0}, {1, 1}, {0, 2}, {0, 3}, {0, 4}};
  const CellPath diagonal_last{{2, 0}, {2, 1}, {2, 2}, {1, 3}, {0, 4}};
  eaci::EndHeadings east_at_goal;
  east_at_goal.goal = 0.0;
  const eaci::TurningPath a = eaci::cheapestTurningPath(grid, start, goal, 1.0, nullptr, east_at_goal);
  ASSERT_TRUE(a.found);
  EXPECT_EQ(a.path, diagonal_first);
  EXPECT_NEAR(a.combined_cost, shortest + kPi / 4, 1e-12);
  eaci::EndHeadings north_east_at_goal;
  north_east_at_goal.goal = kPi / 4;
  const eaci::TurningPath b = eaci::cheapestTurningPath(grid, start, goal, 1.0, nullptr, north_east_at_goal);
  ASSERT_TRUE(b.found);
  EXPECT_EQ(b.path, diagonal_last);
  EXPECT_NEAR(b.combined_cost, shortest + kPi / 4, 1e-12);
  eaci::EndHeadings north_east_at_start;
  north_east_at_start.start = kPi / 4 + 2 * kPi;  // any turn count
  const eaci::TurningPath c = eaci::cheapestTurningPath(grid, start, goal, 1.0, nullptr, north_east_at_start);
  ASSERT_TRUE(c.found);
  EXPECT_EQ(c.path, diagonal_first);
  EXPECT_NEAR(c.combined_cost, shortest + kPi / 4, 1e-12);
  // Facing away at the start (west) and at the goal (south): both ends pay, and no detour pays
  // less (G can only be entered heading north, north-east or east, 90 degrees or more off south).
  eaci::EndHeadings away;
  away.start = kPi;
  away.goal = -kPi / 2;
  const eaci::TurningPath d = eaci::cheapestTurningPath(grid, start, goal, 1.0, nullptr, away);
  ASSERT_TRUE(d.found);
  EXPECT_NEAR(d.cost, shortest, 1e-12);
  // NE NE E E: 135 (start) + 45 + 90 (goal) = 270 degrees; E E NE NE: 180 + 45 + 135 = 360.
  EXPECT_EQ(d.path, diagonal_first);
  EXPECT_NEAR(d.combined_cost, shortest + 1.5 * kPi, 1e-12);
  // The plan's own combined cost prices the same ends.
  eaci::Parameters params;
  params.turn_cost = 1.0;
  eaci::PlanOptions options;
  options.end_headings = north_east_at_goal;
  const eaci::PlanResult r = eaci::plan(grid, start, goal, eaci::Algorithm::kAStar, params, options);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_EQ(r.path, diagonal_last);
  EXPECT_NEAR(r.combined_cost, shortest + kPi / 4, 1e-12);
}

TEST(HeadingSearch, WithoutATurnCostItFindsTheAStarOptimum) {
  for (std::uint64_t seed = 200; seed < 230; ++seed) {
    const TestMap m = randomMap(seed, 7, 7, 0.25, seed % 2 == 0);
    const CostGrid grid = m.grid();
    const auto astar = eaci::cheapestPath(grid, Cell{0, 0}, Cell{6, 6});
    const eaci::TurningPath p = eaci::cheapestTurningPath(grid, Cell{0, 0}, Cell{6, 6}, 0.0);
    ASSERT_EQ(p.found, astar.found) << "seed " << seed;
    if (!p.found) continue;
    EXPECT_NEAR(p.combined_cost, astar.cost, 1e-9) << "seed " << seed;
    EXPECT_NEAR(p.cost, stateGraphDijkstra(m, Cell{0, 0}, Cell{6, 6}, 0.0), 1e-9) << "seed " << seed;
  }
}

// --- Stopping, memory, and the planner's entry point -----------------------------------------

TEST(HeadingSearch, StopsWhenTheStopCheckSaysSo) {
  const CostGrid grid = CostGrid::fromRows(std::vector<std::vector<int>>(40, std::vector<int>(40, 0)), false);
  int calls = 0;
  const auto stop_now = [&calls] {
    ++calls;
    return true;
  };
  eaci::StopPoll poll(stop_now, 0, 1);
  const eaci::TurningPath p = eaci::cheapestTurningPath(grid, Cell{0, 0}, Cell{39, 39}, 1.0, &poll);
  EXPECT_TRUE(p.stopped);
  EXPECT_FALSE(p.found);
  EXPECT_EQ(calls, 1);
}

TEST(HeadingSearch, KeepsCostLabelsOnlyForTheFrontier) {
  // 200 x 200 open cells and a goal walled in: the search settles states on every cell it can
  // reach and finds no route, but blocks of 8 cost labels exist only for the cells with open
  // states at the same time (the frontier): fewer than a quarter of the cells.
  const CostGrid grid = walledInGoal(200);
  eaci::HeadingSearch search;
  const eaci::TurningPath p = search.cheapestPath(grid, Cell{0, 0}, Cell{199, 199}, 2.0);
  EXPECT_FALSE(p.found);
  EXPECT_GE(search.stats().settled, 200u * 200u - 4u);
  EXPECT_LT(search.stats().open_blocks * 4, grid.cellCount());  // measured: 6,853 of 40,000
}

TEST(HeadingSearch, PlanUsesItForAStarWheneverTurnCostIsPositive) {
  const TestMap m = fromRows({{0, 0, 0, 0, 0, 0, 0}, {0, 0, 0, 1, 0, 0, 0}, {0, 0, 0, 0, 0, 0, 0}}, false);
  const CostGrid grid = m.grid();
  eaci::Parameters params;
  params.turn_cost = 1.0;
  const eaci::PlanResult r = eaci::plan(grid, Cell{1, 0}, Cell{1, 6}, eaci::Algorithm::kAStar, params);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_NEAR(r.combined_cost, bruteForce(m, Cell{1, 0}, Cell{1, 6}, 1.0), 1e-9);
  EXPECT_NEAR(r.combined_cost, r.cost + 1.0 * r.total_turn_deg * kPi / 180.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.total_turn_deg, 90.0);
  // turn_cost 0: A* itself, route for route; the combined cost is the cost.
  params.turn_cost = 0.0;
  const eaci::PlanResult plain = eaci::plan(grid, Cell{1, 0}, Cell{1, 6}, eaci::Algorithm::kAStar, params);
  ASSERT_TRUE(plain.success());
  EXPECT_EQ(plain.path, eaci::cheapestPath(grid, Cell{1, 0}, Cell{1, 6}).path);
  EXPECT_EQ(plain.combined_cost, plain.cost);
  // A plan kept in a workspace gives what a fresh one gives.
  eaci::PlannerWorkspace workspace;
  eaci::PlanOptions options;
  options.workspace = &workspace;
  params.turn_cost = 1.0;
  for (int k = 0; k < 2; ++k) {
    const eaci::PlanResult kept = eaci::plan(grid, Cell{1, 0}, Cell{1, 6}, eaci::Algorithm::kAStar, params, options);
    EXPECT_EQ(kept.path, r.path);
  }
  // Other algorithms report the combined cost of their route too.
  const eaci::PlanResult colony = eaci::plan(grid, Cell{1, 0}, Cell{1, 6}, eaci::Algorithm::kEaci, params);
  ASSERT_TRUE(colony.success());
  EXPECT_NEAR(colony.combined_cost, testCombinedCost(m, colony.path, 1.0), 1e-9);
}

TEST(HeadingSearch, PlanStopsInsideTheSearch) {
  const CostGrid grid = walledInGoal(200);  // the search would take every state off its open list
  eaci::Parameters params;
  params.turn_cost = 0.5;
  eaci::PlanOptions options;
  int calls = 0;
  options.should_stop = [&calls](int) { return ++calls >= 2; };  // the first call in the loop says go on
  const eaci::PlanResult r = eaci::plan(grid, Cell{0, 0}, Cell{199, 199}, eaci::Algorithm::kAStar, params, options);
  EXPECT_EQ(r.status, eaci::PlanStatus::kStopped);
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(calls, 2);
}

// --- turn_cost_unit route_cell (planner/turn_cost_unit.hpp) ------------------------------------

// By hand on a corridor: free, three cells of cost 50, free. A move into a cell of cost 50 costs
// (50 + 3 x 50) / 50 = 4, into a free one 1: the cheapest route costs 4 + 4 + 4 + 1 = 13 over 4
// cells, its average cell 13 / 4, and a radian is priced at turn_cost x 13 / 4.
TEST(TurnCostUnit, RouteCellPricesARadianAtTheCheapestRoutesAverageCell) {
  TestMap m;
  m.rows = 1;
  m.cols = 5;
  m.cost = {0, 50, 50, 50, 0};
  const CostGrid grid = m.grid();
  eaci::Parameters params;
  params.turn_cost = 2.0;
  for (const eaci::Algorithm algorithm : {eaci::Algorithm::kAStar, eaci::Algorithm::kEaci}) {
    params.turn_cost_unit = eaci::TurnCostUnit::kFreeCell;
    const eaci::PlanResult as_it_is = eaci::plan(grid, Cell{0, 0}, Cell{0, 4}, algorithm, params);
    ASSERT_TRUE(as_it_is.success()) << as_it_is.error;
    EXPECT_EQ(as_it_is.turn_price, 2.0);
    params.turn_cost_unit = eaci::TurnCostUnit::kRouteCell;
    const eaci::PlanResult in_route_cells = eaci::plan(grid, Cell{0, 0}, Cell{0, 4}, algorithm, params);
    ASSERT_TRUE(in_route_cells.success()) << in_route_cells.error;
    EXPECT_NEAR(in_route_cells.turn_price, 2.0 * 13.0 / 4.0, 1e-12);
    EXPECT_NEAR(in_route_cells.combined_cost, 13.0, 1e-12);  // straight on: no turn to price
  }
  // Start = goal: nothing to measure, nothing to turn.
  EXPECT_EQ(eaci::plan(grid, Cell{0, 2}, Cell{0, 2}, eaci::Algorithm::kAStar, params).combined_cost, 0.0);
  EXPECT_EQ(eaci::routeCellCost(13.0, 4.0), 13.0 / 4.0);
  EXPECT_EQ(eaci::routeCellCost(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()), 1.0);
  EXPECT_EQ(eaci::routeCellCost(0.0, 0.0), 1.0);
}

// A map whose free cells all cost 50 prices every move at 4 x its length, so every route's
// average cell costs 4 and route_cell prices a radian at 4 x turn_cost: the whole objective is
// 4 x the one of the same map with free cells, and so is its optimum (brute force on both).
// In free cells the same turn_cost weighs 4 x less against the moves: the brute force at t.
TEST(TurnCostUnit, OnAUniformlyCostlyMapRouteCellPlansAsOnTheFreeMap) {
  int planned = 0;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    const TestMap free_map = randomMap(seed, 5, 6, 0.25, false);
    TestMap costly = free_map;
    for (int& c : costly.cost)
      if (c >= 0) c = 50;
    const Cell start{0, 0}, goal{4, 5};
    const double t = 0.5 + 0.5 * static_cast<double>(seed % 4);
    const double free_optimum = bruteForce(free_map, start, goal, t);
    eaci::Parameters params;
    params.turn_cost = t;
    params.turn_cost_unit = eaci::TurnCostUnit::kRouteCell;
    const eaci::PlanResult r = eaci::plan(costly.grid(), start, goal, eaci::Algorithm::kAStar, params);
    if (!std::isfinite(free_optimum)) {
      EXPECT_EQ(r.status, eaci::PlanStatus::kNoPath) << "seed " << seed;
      continue;
    }
    ++planned;
    ASSERT_TRUE(r.success()) << "seed " << seed << ": " << r.error;
    EXPECT_NEAR(r.turn_price, 4.0 * t, 1e-12) << "seed " << seed;
    EXPECT_NEAR(r.combined_cost, 4.0 * free_optimum, 1e-9) << "seed " << seed;
    EXPECT_NEAR(testCombinedCost(costly, r.path, 4.0 * t), r.combined_cost, 1e-9) << "seed " << seed;
    params.turn_cost_unit = eaci::TurnCostUnit::kFreeCell;
    const eaci::PlanResult as_it_is = eaci::plan(costly.grid(), start, goal, eaci::Algorithm::kAStar, params);
    EXPECT_NEAR(as_it_is.combined_cost, bruteForce(costly, start, goal, t), 1e-9) << "seed " << seed;
  }
  EXPECT_GE(planned, 8);
}

TEST(TurnCostUnit, APlanStopsInsideTheMeasuringSearch) {
  const CostGrid grid = walledInGoal(200);  // A* would take every cell off its open list
  eaci::Parameters params;
  params.turn_cost = 0.5;
  params.turn_cost_unit = eaci::TurnCostUnit::kRouteCell;
  eaci::PlanOptions options;
  int calls = 0;
  options.should_stop = [&calls](int) { return ++calls >= 2; };
  const eaci::PlanResult r = eaci::plan(grid, Cell{0, 0}, Cell{199, 199}, eaci::Algorithm::kAStar, params, options);
  EXPECT_EQ(r.status, eaci::PlanStatus::kStopped);
  EXPECT_TRUE(r.interrupted);
  EXPECT_NE(r.error.find("route_cell"), std::string::npos) << r.error;
}
