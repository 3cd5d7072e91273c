// Maps of costs: saveRawMap (eaci/io/map_server_writer.hpp) read back by loadMapServerYaml in raw
// mode, and planning on a raw map with its costs.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "eaci/io/map_io.hpp"
#include "test_support.hpp"
#include "eaci/io/map_server_writer.hpp"
#include "eaci/planner.hpp"

namespace eaci {
namespace {

namespace fs = std::filesystem;

class RawMaps : public eaci::test::ScratchDirTest {
 protected:
  RawMaps() : ScratchDirTest("test_raw_maps_tmp") {}
  static std::string read(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream(path(name), std::ios::binary) << bytes;
    return path(name);
  }

};

// A costmap-like buffer: bottom row first, as costmap_2d stores it.
//   top    row (buffer row 2): 255 254 253 252   0
//   middle row (buffer row 1):   1   2   3 128 200
//   bottom row (buffer row 0):  10  20  30  40  50
const std::vector<std::uint8_t> kBottomFirst = {10, 20, 30, 40, 50, 1, 2, 3, 128, 200, 255, 254, 253, 252, 0};
const std::vector<std::uint8_t> kTopFirst = {255, 254, 253, 252, 0, 1, 2, 3, 128, 200, 10, 20, 30, 40, 50};

MapFrame frameOf(int width, int height, double resolution, double x, double y) {
  MapFrame frame;
  frame.width = width;
  frame.height = height;
  frame.resolution = resolution;
  frame.origin = {x, y};
  return frame;
}

TEST_F(RawMaps, SavedMapReadsBackWithTheSameCostsAndFrame) {
  const GridView costs(kBottomFirst.data(), 5, 3, RowOrder::kBottomFirst);
  const MapFrame frame = frameOf(5, 3, 0.05, -3.25, 0.1 + 0.2);  // 0.30000000000000004: must survive exactly
  const SavedMapFiles files = saveRawMap(path("saved.yaml"), costs, frame, {"request: start (1, 2)", "two\nlines"});
  EXPECT_EQ(files.yaml_path, path("saved.yaml"));
  EXPECT_EQ(files.image_path, path("saved.pgm"));

  // The PGM: header, then the top row (the costmap's last buffer row) first.
  EXPECT_EQ(read(files.image_path), "P5\n5 3\n255\n" + std::string(kTopFirst.begin(), kTopFirst.end()));
  const std::string yaml = read(files.yaml_path);
  EXPECT_EQ(yaml.rfind("# request: start (1, 2)\n# two lines\n", 0), 0u) << yaml;
  for (const char* line : {"image: saved.pgm\n", "mode: raw\n", "negate: 0\n", "occupied_thresh: 0.65\n",
                           "free_thresh: 0.196\n", "resolution: 0.05\n"})
    EXPECT_NE(yaml.find(line), std::string::npos) << line << " missing from\n" << yaml;

  const OccupancyMap map = loadMapServerYaml(files.yaml_path);
  EXPECT_EQ(map.values, CellValues::kCostmapCosts);
  EXPECT_EQ(map.width, 5);
  EXPECT_EQ(map.height, 3);
  EXPECT_EQ(map.cells, kTopFirst);
  EXPECT_EQ(map.resolution, 0.05);
  EXPECT_EQ(map.origin.x(), -3.25);
  EXPECT_EQ(map.origin.y(), 0.1 + 0.2);
  EXPECT_EQ(map.origin_yaw, 0.0);
  // The same cell under the same world point in both.
  const auto cell = map.worldToCell({-3.25 + 3.5 * 0.05, 0.30000000000000004 + 0.5 * 0.05});  // column 3, bottom row
  ASSERT_TRUE(cell.has_value());
  EXPECT_EQ(map.view().value(*cell), 40);
}

TEST_F(RawMaps, SavingRefusesWhatCannotBeAMap) {
  const GridView costs(kBottomFirst.data(), 5, 3, RowOrder::kBottomFirst);
  const auto error = [&](const std::string& file, const MapFrame& frame) -> std::string {
    try {
      saveRawMap(file, costs, frame);
    } catch (const MapSaveError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error(path("a.yaml"), frameOf(4, 3, 0.05, 0, 0)).find("5 x 3 cells, its frame 4 x 3"), std::string::npos);
  EXPECT_NE(error(path("b.yaml"), frameOf(5, 3, 0.0, 0, 0)).find("resolution 0 is not a positive number"),
            std::string::npos);
  EXPECT_NE(error(path("c.yaml"), frameOf(5, 3, 1, NAN, 0)).find("origin is not finite"), std::string::npos);
  const std::string missing = path("no/such/dir/d.yaml");
  const std::string message = error(missing, frameOf(5, 3, 1, 0, 0));
  EXPECT_NE(message.find("cannot save map " + path("no/such/dir/d.pgm")), std::string::npos) << message;
}

// A raw map written by hand (not by saveRawMap), 2 rows x 3 columns of costs:
//   row 0:  0  50  0      start (0, 0), goal (0, 2)
//   row 1:  0  10  0
// With the default cost rule (neutral 50, factor 3) a move into a cell of cost c costs
// step x (50 + 3c) / 50. By hand:
//   straight through (0, 1):           1 x 200/50 + 1          = 5
//   (0,0) -> (1,1) -> (0,2) diagonals: sqrt2 x 80/50 + sqrt2 x 1 = 2.6 sqrt2 = 3.677
//   (0,0) -> (1,0) -> (1,1) -> (1,2) -> (0,2): 1 + 1.6 + 1 + 1 = 4.6
// The diagonals pass the corner of (0, 1), a cell with a cost but free, so they are allowed.
TEST_F(RawMaps, AStarOnARawMapPaysTheCellCosts) {
  write("tiny.pgm", std::string("P5\n3 2\n255\n") + std::string{0, 50, 0, 0, 10, 0});
  const OccupancyMap map = loadMapServerYaml(write("tiny.yaml", "image: tiny.pgm\nmode: raw\nresolution: 1\n"
                                                                "origin: [0, 0, 0]\nnegate: 0\n"
                                                                "occupied_thresh: 0.65\nfree_thresh: 0.196\n"));
  const PlanResult r = plan(map.view(), Cell{0, 0}, Cell{0, 2}, Algorithm::kAStar, Parameters{});
  ASSERT_TRUE(r.success()) << r.error;
  EXPECT_EQ(r.path, (CellPath{Cell{0, 0}, Cell{1, 1}, Cell{0, 2}}));
  EXPECT_NEAR(r.cost, 2.6 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(r.length, 2 * std::sqrt(2.0), 1e-12);

  // With lethal_cost 50 the cell (0, 1) is an obstacle: no diagonal may pass its corner, and the
  // only route left goes round through row 1: 1 + 1.6 + 1 + 1 = 4.6.
  Parameters lethal50;
  lethal50.lethal_cost = 50;
  const PlanResult walled = plan(map.view(UnknownPolicy::kObstacle, 50), Cell{0, 0}, Cell{0, 2}, Algorithm::kAStar, lethal50);
  ASSERT_TRUE(walled.success()) << walled.error;
  EXPECT_EQ(walled.path, (CellPath{Cell{0, 0}, Cell{1, 0}, Cell{1, 1}, Cell{1, 2}, Cell{0, 2}}));
  EXPECT_NEAR(walled.cost, 4.6, 1e-12);
}

}  // namespace
}  // namespace eaci
