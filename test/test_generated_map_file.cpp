// eaci_bench map: a generated map written by saveTrinaryMap (eaci/io/map_server_writer.hpp)
// reads back through loadMap with the same cells, resolution and origin; the generator's room
// and door widths (src/bench/map_generator.hpp) are kept.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

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
