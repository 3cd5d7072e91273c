// Unknown cells (a SLAM map that holds unexplored space, issue #27): with allow_unknown they are
// passable at the dearest passable cost, as navfn and global_planner price them, so a route
// crosses unknown space only where every way round through known space costs more; without
// it they are obstacles. Each route's cost is checked against the suite's reference Dijkstra
// (test_support.hpp) with the unknown rule written out below, not read from the planner.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "eaci/io/occupancy_map.hpp"
#include "eaci/planner.hpp"
#include "test_support.hpp"

using eaci::Algorithm;
using eaci::Cell;
using eaci::PlanStatus;

namespace {

constexpr char kFree = '.';
constexpr char kWall = '#';
constexpr char kUnknown = '?';

// The dearest passable cost on the costmap scale (costmap_2d: INSCRIBED_INFLATED_OBSTACLE 253 - 1).
constexpr int kUnknownCost = 252;

// A map-file-style occupancy map (not graded: known free cells cost 0) from rows of
// '.' free, '#' occupied, '?' unknown; first row = top.
eaci::OccupancyMap occupancyMap(const std::vector<std::string>& rows) {
  eaci::OccupancyMap map;
  map.height = static_cast<int>(rows.size());
  map.width = static_cast<int>(rows.front().size());
  for (const std::string& row : rows)
    for (char c : row)
      map.cells.push_back(c == kWall ? eaci::kOccupiedValue : c == kUnknown ? eaci::kUnknownValue : eaci::kFreeValue);
  return map;
}

// The rule written out: a wall is closed; an unknown cell is closed unless unknown cells are
// allowed, and then costs 252; a known free cell costs 0. Moves as in the reference.
double referenceCost(const std::vector<std::string>& rows, Cell start, Cell goal, bool allow_unknown) {
  eaci::test::ReferenceGrid g;
  g.height = static_cast<int>(rows.size());
  g.width = static_cast<int>(rows.front().size());
  g.open = [&](int r, int c) { return rows[r][c] == kFree || (rows[r][c] == kUnknown && allow_unknown); };
  g.cost = [&](int r, int c) { return rows[r][c] == kUnknown ? kUnknownCost : 0; };
  return eaci::test::referenceCosts(g, start)[static_cast<std::size_t>(goal.row) * g.width + goal.col];
}

eaci::PlanResult planOn(const eaci::OccupancyMap& map, Cell start, Cell goal, bool allow_unknown,
                        Algorithm algorithm = Algorithm::kAStar) {
  eaci::Parameters params;
  params.allow_unknown = allow_unknown;
  const eaci::UnknownPolicy unknown = allow_unknown ? eaci::UnknownPolicy::kExpensive : eaci::UnknownPolicy::kObstacle;
  return eaci::plan(map.view(unknown), start, goal, algorithm, params);
}

int unknownCellsOn(const std::vector<std::string>& rows, const eaci::CellPath& path) {
  int count = 0;
  for (const Cell& c : path) count += rows[c.row][c.col] == kUnknown ? 1 : 0;
  return count;
}

}  // namespace

TEST(UnknownSpace, OneUnknownCellCostsTheDearestPassableCost) {
  // A corridor whose middle cell is unknown: 4 straight moves, one of them into the unknown cell,
  // which costs 1 x (50 + 3 x 252) / 50 = 16.12; the other three cost 1 each.
  const std::vector<std::string> rows = {"..?.."};
  const auto r = planOn(occupancyMap(rows), Cell{0, 0}, Cell{0, 4}, true);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_NEAR(r.cost, 3.0 + 806.0 / 50.0, 1e-9);
  EXPECT_NEAR(r.cost, referenceCost(rows, Cell{0, 0}, Cell{0, 4}, true), 1e-9);
}

TEST(UnknownSpace, RouteGoesRoundAnUnknownBlockWhenKnownSpaceIsCheaper) {
  // An unknown block between start and goal, known free space below it: the way round costs
  // a few moves more than the straight line, far less than one unknown cell.
  const std::vector<std::string> rows = {
      "..???..",
      "..???..",
      "..???..",
      "..???..",
      ".......",
  };
  const Cell start{1, 0}, goal{1, 6};
  const double expected = referenceCost(rows, start, goal, true);
  ASSERT_LT(expected, 16.0);  // the reference goes round too
  for (Algorithm algorithm : {Algorithm::kAStar, Algorithm::kEaci}) {
    const auto r = planOn(occupancyMap(rows), start, goal, true, algorithm);
    ASSERT_TRUE(r.success()) << eaci::toString(algorithm) << ": " << r.error;
    EXPECT_EQ(unknownCellsOn(rows, r.path), 0) << eaci::toString(algorithm);
    EXPECT_NEAR(r.cost, expected, 1e-9) << eaci::toString(algorithm);
  }
}

TEST(UnknownSpace, RouteCrossesUnknownSpaceWhenNoKnownWayExists) {
  // An unknown wall from top to bottom: the cheapest route crosses it at one cell.
  const std::vector<std::string> rows = {
      "...?...",
      "...?...",
      "...?...",
  };
  const Cell start{1, 0}, goal{1, 6};
  const auto r = planOn(occupancyMap(rows), start, goal, true);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_EQ(unknownCellsOn(rows, r.path), 1);
  EXPECT_NEAR(r.cost, 5.0 + 806.0 / 50.0, 1e-9);  // six straight moves, one into the unknown cell
  EXPECT_NEAR(r.cost, referenceCost(rows, start, goal, true), 1e-9);
}

TEST(UnknownSpace, RouteCrossesUnknownSpaceOnlyWhereTheDetourCostsMore) {
  // An unknown wall with a gap of known space at the bottom. Near the gap the detour through it
  // is cheaper than an unknown cell (16.12); at the top it is longer (about 2 x 9 moves).
  const std::vector<std::string> rows = {
      "....?....",
      "....?....",
      "....?....",
      "....?....",
      "....?....",
      "....?....",
      "....?....",
      "....?....",
      "....?....",
      ".........",
  };
  const Cell far_start{0, 3}, far_goal{0, 5};
  const auto far = planOn(occupancyMap(rows), far_start, far_goal, true);
  ASSERT_TRUE(far.success()) << far.error;
  EXPECT_EQ(unknownCellsOn(rows, far.path), 1);
  EXPECT_NEAR(far.cost, 1.0 + 806.0 / 50.0, 1e-9);  // straight across: into the unknown cell, then out
  EXPECT_NEAR(far.cost, referenceCost(rows, far_start, far_goal, true), 1e-9);

  const Cell near_start{7, 3}, near_goal{7, 5};
  const auto near = planOn(occupancyMap(rows), near_start, near_goal, true);
  ASSERT_TRUE(near.success()) << near.error;
  EXPECT_EQ(unknownCellsOn(rows, near.path), 0);
  // Down a row, diagonally into the gap, diagonally out of it, up a row: 2 straight + 2 diagonal
  // moves, all into known cells (the diagonals pass the unknown cell's corner: it is passable).
  EXPECT_NEAR(near.cost, 2.0 + 2.0 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(near.cost, referenceCost(rows, near_start, near_goal, true), 1e-9);
}

TEST(UnknownSpace, UnknownAsObstacleLeavesNoRouteWhereOnlyUnknownConnects) {
  const std::vector<std::string> rows = {
      "...?...",
      "...?...",
      "...?...",
  };
  EXPECT_FALSE(std::isfinite(referenceCost(rows, Cell{1, 0}, Cell{1, 6}, false)));
  for (Algorithm algorithm : {Algorithm::kAStar, Algorithm::kEaci}) {
    const auto r = planOn(occupancyMap(rows), Cell{1, 0}, Cell{1, 6}, false, algorithm);
    EXPECT_EQ(r.status, PlanStatus::kNoPath) << eaci::toString(algorithm);
  }
}

TEST(UnknownSpace, CostmapUnknownCostsLethalCostMinusOne) {
  // costmap_2d bytes: 255 unknown, 253 inscribed (an obstacle with lethal_cost 253). The row
  // 0 0 255 0 0 with lethal_cost 253 costs 3 + (50 + 3 x 252) / 50; with lethal_cost 200 the
  // unknown cell costs 199: 3 + (50 + 3 x 199) / 50.
  const std::vector<std::uint8_t> bytes = {0, 0, 255, 0, 0};
  eaci::Parameters params;
  params.allow_unknown = true;
  const eaci::GridView view253(bytes.data(), 5, 1, eaci::RowOrder::kTopFirst, eaci::CellInterpretation::costmap(253, true));
  const auto r253 = eaci::plan(view253, Cell{0, 0}, Cell{0, 4}, Algorithm::kAStar, params);
  ASSERT_TRUE(r253.success()) << r253.error;
  EXPECT_NEAR(r253.cost, 3.0 + 806.0 / 50.0, 1e-9);
  params.lethal_cost = 200;
  const eaci::GridView view200(bytes.data(), 5, 1, eaci::RowOrder::kTopFirst, eaci::CellInterpretation::costmap(200, true));
  const auto r200 = eaci::plan(view200, Cell{0, 0}, Cell{0, 4}, Algorithm::kAStar, params);
  ASSERT_TRUE(r200.success()) << r200.error;
  EXPECT_NEAR(r200.cost, 3.0 + 647.0 / 50.0, 1e-9);
  // Without allow_unknown the unknown cell closes the row.
  const eaci::GridView closed(bytes.data(), 5, 1, eaci::RowOrder::kTopFirst, eaci::CellInterpretation::costmap(253, false));
  EXPECT_EQ(eaci::plan(closed, Cell{0, 0}, Cell{0, 4}, Algorithm::kAStar, params).status, PlanStatus::kNoPath);
}
