// The colony's region (beyond the paper): the cells within a margin of the cheapest route,
// numbered compactly, with moves that never leave it.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "eaci/aco/auxiliary_map.hpp"
#include "eaci/aco/colony_region.hpp"
#include "eaci/planner.hpp"
#include "eaci/search/astar.hpp"
#include "test_support.hpp"

using eaci::Cell;
using eaci::CellPath;
using eaci::ColonyRegion;
using eaci::CostGrid;

namespace {

constexpr int kEast = 0, kNorthEast = 1, kNorth = 2, kNorthWest = 3, kWest = 4, kSouthWest = 5, kSouth = 6,
              kSouthEast = 7;
constexpr std::uint32_t kNone = ColonyRegion::kNone;

CostGrid emptyGrid(int rows, int cols) {
  return CostGrid::fromRows(std::vector<std::vector<int>>(rows, std::vector<int>(cols, 0)), false);
}

std::uint32_t regionCell(const ColonyRegion& region, const CostGrid& grid, Cell c) {
  return region.regionIndex(grid.index(c));
}

}  // namespace

TEST(ColonyRegion, HoldsTheCellsWithinTheMarginNumberedInGridOrder) {
  // 5 x 6 open grid, route (2,0) -> (2,1), margin 1: rows 1..3, columns 0..2.
  const CostGrid grid = emptyGrid(5, 6);
  const ColonyRegion region = ColonyRegion::aroundRoute(grid, {Cell{2, 0}, Cell{2, 1}}, 1);
  ASSERT_EQ(region.size(), 9u);
  const Cell expected[] = {{1, 0}, {1, 1}, {1, 2}, {2, 0}, {2, 1}, {2, 2}, {3, 0}, {3, 1}, {3, 2}};
  for (std::uint32_t r = 0; r < 9; ++r) {
    EXPECT_EQ(grid.cellAt(region.gridIndex(r)), expected[r]) << r;
    EXPECT_EQ(regionCell(region, grid, expected[r]), r);
  }
  EXPECT_EQ(regionCell(region, grid, Cell{0, 0}), kNone);
  EXPECT_EQ(regionCell(region, grid, Cell{2, 3}), kNone);
  EXPECT_EQ(region.gridCellCount(), 30u);
}

TEST(ColonyRegion, NeighboursStopAtTheRegionBoundaryAndTheMapEdge) {
  const CostGrid grid = emptyGrid(5, 6);
  const ColonyRegion region = ColonyRegion::aroundRoute(grid, {Cell{2, 0}, Cell{2, 1}}, 1);
  // (2,2) = 5, on the east boundary: its eastern neighbours (1,3), (2,3), (3,3) are outside.
  const std::uint32_t edge = 5;
  EXPECT_EQ(region.neighbour(edge, kEast), kNone);
  EXPECT_EQ(region.neighbour(edge, kNorthEast), kNone);
  EXPECT_EQ(region.neighbour(edge, kSouthEast), kNone);
  EXPECT_EQ(region.neighbour(edge, kNorth), 2u);      // (1,2)
  EXPECT_EQ(region.neighbour(edge, kNorthWest), 1u);  // (1,1)
  EXPECT_EQ(region.neighbour(edge, kWest), 4u);       // (2,1)
  EXPECT_EQ(region.neighbour(edge, kSouthWest), 7u);  // (3,1)
  EXPECT_EQ(region.neighbour(edge, kSouth), 8u);      // (3,2)
  // (1,0) = 0: the map edge to the west, the region edge to the north.
  for (int d : {kNorthEast, kNorth, kNorthWest, kWest, kSouthWest}) EXPECT_EQ(region.neighbour(0, d), kNone) << d;
  EXPECT_EQ(region.neighbour(0, kEast), 1u);
  EXPECT_EQ(region.neighbour(0, kSouth), 3u);
  EXPECT_EQ(region.neighbour(0, kSouthEast), 4u);
}

TEST(ColonyRegion, MarginCountsMovesSoAWallKeepsCellsBehindItOut) {
  // Route (0,0) -> (1,0), margin 2. The wall in column 1 leaves one way round, through (2,0):
  // (2,0) is one move away, (2,1) two; (1,2) is two columns away but four moves.
  //   0 1 0 0
  //   0 1 0 0
  //   0 0 0 0
  const CostGrid grid = CostGrid::fromRows({{0, 1, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 0}}, false);
  const ColonyRegion region = ColonyRegion::aroundRoute(grid, {Cell{0, 0}, Cell{1, 0}}, 2);
  ASSERT_EQ(region.size(), 4u);
  const Cell expected[] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}};
  for (std::uint32_t r = 0; r < 4; ++r) EXPECT_EQ(grid.cellAt(region.gridIndex(r)), expected[r]) << r;
  // (2,1) = 3: west is (2,0); north is the wall; north-east (1,2) and east (2,2) are free but
  // outside; north-west (1,0) would cut the wall's corner.
  EXPECT_EQ(region.neighbour(3, kWest), 2u);
  EXPECT_EQ(region.neighbour(3, kNorth), kNone);
  EXPECT_EQ(region.neighbour(3, kNorthEast), kNone);
  EXPECT_EQ(region.neighbour(3, kEast), kNone);
  EXPECT_EQ(region.neighbour(3, kNorthWest), kNone);
  // (1,0) = 1: south-east to (2,1) would cut the wall's corner too.
  EXPECT_EQ(region.neighbour(1, kSouthEast), kNone);
  EXPECT_EQ(region.neighbour(1, kSouth), 2u);
}

// A route across the map, corner to corner: its bounding box is the whole map, its region the
// cells within 2 moves of a diagonal cell, the band |row - col| <= 4: 300 + 2 x (299 + 298 +
// 297 + 296) = 2680 cells, numbered in grid order, each with the neighbours the band holds.
TEST(ColonyRegion, ARouteAcrossTheMapHoldsTheBandAlongIt) {
  const CostGrid grid = emptyGrid(300, 300);
  CellPath diagonal;
  for (int k = 0; k < 300; ++k) diagonal.push_back(Cell{k, k});
  const ColonyRegion region = ColonyRegion::aroundRoute(grid, diagonal, 2);
  ASSERT_EQ(region.size(), 2680u);
  std::uint32_t expected_number = 0;
  for (int r = 0; r < 300; ++r)
    for (int c = 0; c < 300; ++c) {
      const bool in_band = std::abs(r - c) <= 4;
      const std::uint32_t number = regionCell(region, grid, Cell{r, c});
      ASSERT_EQ(number, in_band ? expected_number : kNone) << r << "," << c;
      if (!in_band) continue;
      ++expected_number;
      EXPECT_EQ(region.neighbour(number, kEast) != kNone, c + 1 < 300 && std::abs(r - c - 1) <= 4) << r << "," << c;
      EXPECT_EQ(region.neighbour(number, kSouthEast) != kNone, r + 1 < 300 && c + 1 < 300) << r << "," << c;
    }
  // (150, 152): after the band's cells of rows 0-149 (5 + 6 + 7 + 8 + 9 x 146 = 1340) and
  // (150, 146..151): 1346. Its south-west neighbour is (151, 151).
  const std::uint32_t at = regionCell(region, grid, Cell{150, 152});
  EXPECT_EQ(at, 1346u);
  EXPECT_EQ(region.neighbour(at, kSouthWest), regionCell(region, grid, Cell{151, 151}));
}

TEST(ColonyRegion, WholeMapNumbersCellsByGridIndexAndMovesByTheGridsRule) {
  const CostGrid grid = CostGrid::fromRows({{0, 1, 0}, {0, 0, 0}}, false);
  const ColonyRegion region = ColonyRegion::wholeMap(grid);
  ASSERT_EQ(region.size(), 6u);
  EXPECT_EQ(region.gridCellCount(), 6u);
  for (std::uint32_t r = 0; r < 6; ++r) {
    EXPECT_EQ(region.gridIndex(r), r);
    EXPECT_EQ(region.regionIndex(std::size_t{r}), r);
  }
  EXPECT_EQ(region.neighbour(0, kEast), kNone);       // (0,1) is an obstacle
  EXPECT_EQ(region.neighbour(0, kSouth), 3u);         // (1,0)
  EXPECT_EQ(region.neighbour(0, kSouthEast), kNone);  // would cut the obstacle's corner
  EXPECT_EQ(region.neighbour(3, kEast), 4u);
  EXPECT_EQ(region.neighbour(3, kWest), kNone);       // off the map
}

TEST(ColonyRegion, EquationTwelvePerCellAgreesWithTheAuxiliaryMap) {
  for (const auto& pc : eaci::test::paperCases()) {
    const CostGrid grid = eaci::test::paperMap(pc.file, false);
    const CostGrid aux = eaci::auxiliaryMap(grid, pc.start, pc.goal);
    for (std::size_t i = 0; i < grid.cellCount(); ++i)
      EXPECT_EQ(eaci::freeOnAuxiliaryMap(grid, grid.cellAt(i), pc.start, pc.goal), aux.isFree(grid.cellAt(i)))
          << pc.file << " cell " << i;
  }
}

// EACI with the pheromone picture on a 30 x 30 open map from (15, 0) to (15, 29): the only
// shortest route is row 15.
static eaci::PlanResult planAlongRow15(int region_margin, int iterations) {
  const CostGrid grid = emptyGrid(30, 30);
  eaci::Parameters params;
  params.ants = 10;
  params.max_iterations = iterations;
  params.region_margin = region_margin;
  eaci::PlanOptions options;
  options.record_pheromone = true;
  return eaci::plan(grid, Cell{15, 0}, Cell{15, 29}, eaci::Algorithm::kEaci, params, options);
}

TEST(ColonyRegion, PheromonePictureIsZeroOutsideTheRegion) {
  // With margin 3 the ants walk on rows 12..18 and nowhere else.
  const CostGrid grid = emptyGrid(30, 30);
  const eaci::PlanResult r = planAlongRow15(3, 5);
  ASSERT_TRUE(r.success()) << r.error;
  ASSERT_EQ(r.pheromone.size(), grid.cellCount());
  for (std::size_t i = 0; i < grid.cellCount(); ++i) {
    const int row = grid.cellAt(i).row;
    if (row >= 12 && row <= 18) EXPECT_GT(r.pheromone[i], 0.0) << "row " << row;
    else EXPECT_EQ(r.pheromone[i], 0.0) << "row " << row;
  }
  for (const Cell& c : r.path) EXPECT_LE(std::abs(c.row - 15), 3);
}

TEST(ColonyRegion, MarginZeroIsTheWholeMapAndANegativeMarginIsRefused) {
  const CostGrid grid = emptyGrid(30, 30);
  const eaci::PlanResult r = planAlongRow15(0, 2);
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_GT(r.pheromone[grid.index(Cell{0, 0})], 0.0);  // 15 rows from the route: in the whole map
  eaci::Parameters params;
  params.region_margin = -1;
  EXPECT_NE(eaci::validationError(params).find("region_margin"), std::string::npos);
}

TEST(ColonyRegion, EaciInANarrowRegionStillReachesTheAStarCost) {
  // A field of pillars with a long way round: a narrow region (margin 2) around A*'s route is
  // all the ants see, and they still find a route as cheap as A*'s.
  std::vector<std::vector<int>> rows(40, std::vector<int>(60, 0));
  for (int r = 2; r < 38; r += 4)
    for (int c = 2; c < 58; c += 4) rows[r][c] = rows[r][c + 1] = rows[r + 1][c] = rows[r + 1][c + 1] = 1;
  for (int r = 0; r < 34; ++r) rows[r][30] = 1;  // a wall open only at the bottom
  const CostGrid grid = CostGrid::fromRows(rows, false);
  const Cell start{1, 1}, goal{1, 58};
  const double optimum = eaci::cheapestPath(grid, start, goal).cost;
  for (int margin : {2, 12}) {
    eaci::Parameters params;
    params.region_margin = margin;
    const eaci::PlanResult r = eaci::plan(grid, start, goal, eaci::Algorithm::kEaci, params);
    ASSERT_TRUE(r.success()) << r.error;
    EXPECT_EQ(eaci::test::routeDefect(grid, r.path, start, goal), "");
    EXPECT_NEAR(r.cost, optimum, 1e-9) << "margin " << margin;
  }
}

TEST(ColonyRegion, GeodesicEaciReportsAnUnreachableGoalWithoutAFlood) {
  const CostGrid grid = CostGrid::fromRows({{0, 1, 0}, {0, 1, 0}}, false);
  const eaci::PlanResult r = eaci::plan(grid, Cell{0, 0}, Cell{1, 2}, eaci::Algorithm::kEaci, eaci::Parameters{});
  EXPECT_EQ(r.status, eaci::PlanStatus::kNoPath) << r.error;
}
