// Saving a costmap for offline replay (src/service/costmap_replay.hpp): the files read back as the
// costmap (bottom row first in the buffer, top row first in the image), the parameters file
// gives the same parameters, and the replay command runs eaci_plan from the same cells.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "costmap_replay.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/planner/parameter_file.hpp"

namespace {

namespace fs = std::filesystem;

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class CostmapReplay : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("eaci_costmap_replay_" + std::to_string(static_cast<long>(::getpid())));
    fs::remove_all(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  fs::path dir_;
};

// 5 x 3 cells of 0.05 m (as costmap_2d holds it: a float widened to double), bottom row first:
//   top    (buffer row 2):   0   0   0   0   0
//   middle (buffer row 1):   0 254 254 254   0      a wall with a gap at each end
//   bottom (buffer row 0):   0  90   0   0   0
eaci_service::CostmapSnapshot labSnapshot() {
  eaci_service::CostmapSnapshot snapshot;
  snapshot.cells = {0, 90, 0, 0, 0, 0, 254, 254, 254, 0, 0, 0, 0, 0, 0};
  snapshot.frame.width = 5;
  snapshot.frame.height = 3;
  snapshot.frame.resolution = static_cast<double>(0.05f);
  snapshot.frame.origin = {-1.2, 0.35};
  snapshot.frame_id = "map";
  return snapshot;
}

TEST_F(CostmapReplay, FilesReadBackAndTheCommandReplaysTheRequest) {
  const eaci_service::CostmapSnapshot costmap = labSnapshot();
  eaci::Parameters params;
  params.lethal_cost = 200;
  params.allow_unknown = true;
  params.seed = 7;
  eaci_service::PlanRecord request;
  request.start = costmap.frame.cellToWorld(eaci::Cell{2, 0});  // bottom left (eaci::Cell row 0 = top)
  request.goal = costmap.frame.cellToWorld(eaci::Cell{2, 4});   // bottom right
  request.tolerance = 0.1;
  request.outcome = "route: cost 8, length 8 cells";
  const eaci_service::ReplayFiles files = eaci_service::saveCostmapForReplay(
      dir_.string(), "snap", costmap, params, eaci::Algorithm::kAStar, request, {"a note"});

  EXPECT_EQ(files.map_yaml, (dir_ / "snap.yaml").string());
  EXPECT_EQ(files.map_image, (dir_ / "snap.pgm").string());
  EXPECT_EQ(files.params_yaml, (dir_ / "snap.params.yaml").string());

  const eaci::OccupancyMap map = eaci::loadMapServerYaml(files.map_yaml);
  EXPECT_EQ(map.values, eaci::CellValues::kCostmapCosts);
  EXPECT_EQ(map.cells, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 254, 254, 254, 0, 0, 90, 0, 0, 0}));
  EXPECT_EQ(map.resolution, static_cast<double>(0.05f));
  EXPECT_EQ(map.origin.x(), -1.2);
  EXPECT_EQ(map.origin.y(), 0.35);

  eaci::Parameters read_back;
  eaci::applyParameterFile(files.params_yaml, read_back, files.params_yaml);
  EXPECT_EQ(eaci::parameterValues(read_back), eaci::parameterValues(params));

  const std::string yaml = readText(files.map_yaml);
  for (const std::string& line : {std::string("# a note\n"), std::string("# route: cost 8, length 8 cells\n"),
                                  "# replay: " + files.command + "\n"})
    EXPECT_NE(yaml.find(line), std::string::npos) << line << " missing from\n" << yaml;
  EXPECT_NE(files.command.find("--algorithm astar"), std::string::npos) << files.command;
  EXPECT_NE(files.command.find("--tolerance 0.1"), std::string::npos) << files.command;

  // The command, run. A* from the bottom-left to the bottom-right cell: straight along the bottom
  // row enters the cost-90 cell, 1 x (50 + 3 x 90) / 50 + 3 = 9.4; round the wall over the top
  // row (no diagonal past a wall cell's corner) costs 8 straight moves, 8.
  const std::string binary = EACI_BINARY_DIR "/bin/eaci_plan";
  ASSERT_TRUE(fs::exists(binary)) << "eaci_plan is built with the tests: " << binary;
  const std::string json_file = (dir_ / "replay.json").string();
  std::string command = files.command;
  command.replace(0, std::string("eaci_plan").size(), binary);
  const int status = std::system((command + " --quiet --json '" + json_file + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
  const nlohmann::json report = nlohmann::json::parse(readText(json_file));
  EXPECT_EQ(report["start"], nlohmann::json::array({2, 0}));
  EXPECT_EQ(report["goal"], nlohmann::json::array({2, 4}));
  EXPECT_DOUBLE_EQ(report["cost"].get<double>(), 8.0);
  EXPECT_EQ(report["path"].size(), 9u);
  EXPECT_EQ(report["parameters"]["lethal_cost"], 200);
}

TEST_F(CostmapReplay, WithoutARequestOnlyTheNotesAreWritten) {
  const eaci_service::ReplayFiles files = eaci_service::saveCostmapForReplay(
      dir_.string(), "plain", labSnapshot(), eaci::Parameters{}, eaci::Algorithm::kEaci, std::nullopt, {"no plan yet"});
  EXPECT_TRUE(files.command.empty());
  const std::string yaml = readText(files.map_yaml);
  EXPECT_EQ(yaml.rfind("# no plan yet\nimage: plain.pgm\n", 0), 0u) << yaml;
}

}  // namespace
