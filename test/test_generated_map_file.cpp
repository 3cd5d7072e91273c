// eaci_bench map: a generated map written by saveTrinaryMap (eaci/io/map_server_writer.hpp)
// reads back through loadMap with the same cells, resolution and origin; the generator's room
// and door widths (src/bench/map_generator.hpp) are kept.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../src/bench/map_command.hpp"
#include "eaci/io/map_io.hpp"
#include "test_support.hpp"
#include "eaci/io/map_server_writer.hpp"

namespace {

namespace fs = std::filesystem;

class GeneratedMapFile : public eaci::test::ScratchDirTest {
 protected:
  GeneratedMapFile() : ScratchDirTest("test_generated_map_file_tmp") {}
};

void expectSameMap(const eaci::OccupancyMap& written, const eaci::OccupancyMap& read) {
  EXPECT_EQ(read.width, written.width);
  EXPECT_EQ(read.height, written.height);
  EXPECT_EQ(read.resolution, written.resolution);
  EXPECT_EQ(read.origin, written.origin);
  EXPECT_EQ(read.values, eaci::CellValues::kOccupancy);
  EXPECT_EQ(read.cells, written.cells);  // row 0 = top in both
}

TEST_F(GeneratedMapFile, BuildingLikeRoomsMapReadsBackWithTheSameCells) {
  eaci_bench::MapCommandOptions options;
  options.size = 150;
  options.seed = 3;
  options.generator = {16, 20, 40, 80};
  options.out_yaml = path("rooms.yaml");
  eaci_bench::GeneratedMap generated;
  const eaci::OccupancyMap map = eaci_bench::generatedMapInMetres(options, generated);
  ASSERT_EQ(map.width, 150);
  EXPECT_EQ(map.resolution, 0.05);
  ASSERT_EQ(eaci_bench::runMapCommand(options), 0);
  expectSameMap(map, eaci::loadMap(options.out_yaml));
}

TEST_F(GeneratedMapFile, ClutterMapAndUnknownCellsReadBack) {
  eaci_bench::MapCommandOptions options;
  options.kind = eaci_bench::MapKind::kClutter;
  options.size = 64;
  options.resolution = 0.1;
  eaci_bench::GeneratedMap generated;
  eaci::OccupancyMap map = eaci_bench::generatedMapInMetres(options, generated);
  map.origin = Eigen::Vector2d(-1.25, 2.5);
  map.cells[5] = eaci::kUnknownValue;
  eaci::saveTrinaryMap(path("clutter.yaml"), map);
  expectSameMap(map, eaci::loadMap(path("clutter.yaml")));
}

// Between wall columns (and from the left edge to the first) lie room_min..room_max free
// columns; after the last wall at least room_min.
TEST_F(GeneratedMapFile, RoomWidthsStayInTheirRange) {
  const eaci_bench::GeneratorOptions options{16, 20, 40, 80};
  const eaci_bench::GeneratedMap g = eaci_bench::generateMap(eaci_bench::MapKind::kRooms, 600, 1, options);
  // Wall columns: occupied in most rows (all but their doors and the crossing walls' doors).
  int walls = 0, previous = -1;
  for (int c = 0; c < g.size; ++c) {
    int occupied = 0;
    for (int r = 0; r < g.size; ++r) occupied += g.map.cells[static_cast<std::size_t>(r) * g.size + c] == eaci::kOccupiedValue;
    if (occupied <= g.size / 2) continue;
    const int room = c - previous - 1;
    EXPECT_GE(room, options.room_min) << "column " << c;
    EXPECT_LE(room, options.room_max) << "column " << c;
    previous = c;
    ++walls;
  }
  EXPECT_GE(walls, 600 / (options.room_max + 1) - 1);
  EXPECT_GE(g.size - 1 - previous, options.room_min);
}

// A 50 x 50 maze with 3-cell corridors and 2-cell walls: pitch 5, (50 + 2) / 5 = 10 maze
// cells a side, the last free row and column 10 * 5 - 2 - 1 = 47 (rows and columns 48-49 wall).
eaci_bench::GeneratedMap smallMaze(std::uint64_t seed) {
  eaci_bench::GeneratorOptions options;
  options.corridor = 3;
  options.maze_wall = 2;
  return eaci_bench::generateMap(eaci_bench::MapKind::kMaze, 50, seed, options);
}

bool freeAt(const eaci_bench::GeneratedMap& g, int row, int col) {
  return g.map.cells[static_cast<std::size_t>(row) * g.size + col] == eaci::kFreeValue;
}

// Every free cell reaches every other (flood fill from the start, 4-neighbours), and there are
// exactly as many free cells as a tree of 10 x 10 maze cells has: 100 squares of 3 x 3 plus
// 99 openings of 3 x 2 = 900 + 594 = 1494 (a loop would open a 100th wall, a cut-off part
// fewer).
TEST_F(GeneratedMapFile, MazeIsPerfectAndEveryFreeCellIsReachable) {
  const eaci_bench::GeneratedMap g = smallMaze(7);
  EXPECT_EQ(g.start, (eaci::Cell{0, 0}));
  EXPECT_EQ(g.goal, (eaci::Cell{47, 47}));
  int free_cells = 0;
  for (int r = 0; r < g.size; ++r)
    for (int c = 0; c < g.size; ++c) free_cells += freeAt(g, r, c);
  EXPECT_EQ(free_cells, 1494);
  std::vector<char> seen(static_cast<std::size_t>(g.size) * g.size, 0);
  std::vector<eaci::Cell> todo{g.start};
  seen[0] = 1;
  int reached = 0;
  while (!todo.empty()) {
    const eaci::Cell cell = todo.back();
    todo.pop_back();
    ++reached;
    const int steps[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    for (const auto& s : steps) {
      const int r = cell.row + s[0], c = cell.col + s[1];
      if (r < 0 || r >= g.size || c < 0 || c >= g.size || !freeAt(g, r, c)) continue;
      if (seen[static_cast<std::size_t>(r) * g.size + c]) continue;
      seen[static_cast<std::size_t>(r) * g.size + c] = 1;
      todo.push_back({r, c});
    }
  }
  EXPECT_EQ(reached, 1494);
  EXPECT_GT(g.optimum, 47.0);  // A* found the goal
}

// Corridors 3 cells wide (every maze-cell square free), walls 2 thick: every wall crossing
// occupied, every wall piece between two maze cells wholly open or wholly closed, the margin
// past row and column 47 occupied.
TEST_F(GeneratedMapFile, MazeCorridorsAndWallsHaveTheAskedWidths) {
  const eaci_bench::GeneratedMap g = smallMaze(3);
  const auto count_free = [&](int top, int left, int height, int width) {
    int n = 0;
    for (int r = top; r < top + height; ++r)
      for (int c = left; c < left + width; ++c) n += freeAt(g, r, c);
    return n;
  };
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      EXPECT_EQ(count_free(i * 5, j * 5, 3, 3), 9) << i << "," << j;
      if (i < 9 && j < 9) {
        EXPECT_EQ(count_free(i * 5 + 3, j * 5 + 3, 2, 2), 0) << i << "," << j;
      }
      if (i < 9) {
        EXPECT_TRUE(count_free(i * 5 + 3, j * 5, 2, 3) % 6 == 0) << "below " << i << "," << j;
      }
      if (j < 9) {
        EXPECT_TRUE(count_free(i * 5, j * 5 + 3, 3, 2) % 6 == 0) << "right of " << i << "," << j;
      }
    }
  EXPECT_EQ(count_free(48, 0, 2, 50), 0);
  EXPECT_EQ(count_free(0, 48, 50, 2), 0);
}

TEST_F(GeneratedMapFile, MazeIsTheSameForASeedAndDiffersAcrossSeeds) {
  EXPECT_EQ(smallMaze(5).map.cells, smallMaze(5).map.cells);
  EXPECT_NE(smallMaze(5).map.cells, smallMaze(6).map.cells);
  // Default widths (3 and 1) on 512 cells: (512 + 1) / 4 = 128 maze cells, last free 510.
  const eaci_bench::GeneratedMap big = eaci_bench::generateMap(eaci_bench::MapKind::kMaze, 512, 1);
  EXPECT_EQ(big.goal, (eaci::Cell{510, 510}));
}

TEST_F(GeneratedMapFile, MazeWidthsBelowOneCellAreRefused) {
  eaci_bench::GeneratorOptions options;
  options.corridor = 0;
  EXPECT_NE(eaci_bench::generatorOptionsProblem(options), "");
  options.corridor = 3;
  options.maze_wall = 0;
  EXPECT_NE(eaci_bench::generatorOptionsProblem(options), "");
  options.maze_wall = 1;
  EXPECT_EQ(eaci_bench::generatorOptionsProblem(options), "");
}

TEST_F(GeneratedMapFile, BadWidthsAreRefused) {
  EXPECT_EQ(eaci_bench::generatorOptionsProblem({16, 20, 40, 80}), "");
  EXPECT_NE(eaci_bench::generatorOptionsProblem({5, 4, 10, 20}), "");
  EXPECT_NE(eaci_bench::generatorOptionsProblem({2, 3, 0, 20}), "");
  EXPECT_THROW(eaci_bench::generateMap(eaci_bench::MapKind::kRooms, 100, 1, {2, 3, 30, 20}), std::runtime_error);
}

TEST_F(GeneratedMapFile, CostMapsAndBadCellValuesAreNotWrittenAsOccupancy) {
  eaci::OccupancyMap map;
  map.width = 2;
  map.height = 1;
  map.cells = {0, 7};
  EXPECT_THROW(eaci::saveTrinaryMap(path("bad.yaml"), map), eaci::MapSaveError);
  map.cells = {0, 100};
  map.values = eaci::CellValues::kCostmapCosts;
  EXPECT_THROW(eaci::saveTrinaryMap(path("costs.yaml"), map), eaci::MapSaveError);
}

}  // namespace
