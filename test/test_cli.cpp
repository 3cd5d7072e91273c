// Runs the built eaci_plan binary (EACI_BINARY_DIR/bin/eaci_plan) and checks its exit status,
// its one-line error messages, its JSON report and its PNG.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>  // header-only
#include <stb_image.h>          // implementation in the linked libstb

#include "eaci/planner/parameters.hpp"
#include "eaci/io/map_io.hpp"
#include "../src/tools/plan_image.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kBinary = EACI_BINARY_DIR "/bin/eaci_plan";
constexpr const char* kPrefix = "eaci_plan: error: ";

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("eaci_cli_" + std::string(info->name()) + "_" + std::to_string(static_cast<long>(::getpid())));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // The build makes eaci_plan before this binary (test/CMakeLists.txt): missing, it is a failure.
    ASSERT_TRUE(fs::exists(kBinary)) << "eaci_plan not built: " << kBinary;
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  fs::path tmp(const std::string& name) const { return dir_ / name; }

  static std::string paperMap(const std::string& name) {
    const std::string path = eaci::test::mapsDir() + "/" + name;
    return path;
  }

  // Runs the CLI with `args` (already shell-quoted where needed).
  CliRun run(const std::string& args) const {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = quote(kBinary) + " " + args + " >" + quote(out.string()) + " 2>" + quote(err.string());
    const int status = std::system(command.c_str());
    CliRun r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readFile(out);
    r.err = readFile(err);
    return r;
  }

  // Runs with --json and returns the report (empty object if none was written).
  json runJson(const std::string& args, CliRun* result = nullptr) const {
    const fs::path report = dir_ / "report.json";
    fs::remove(report);
    const CliRun r = run(args + " --json " + quote(report.string()));
    if (result) *result = r;
    if (!fs::exists(report)) return json::object();
    return json::parse(readFile(report));
  }

  // Expects exit 2 with exactly one line on stderr, "eaci_plan: error: ..."; returns the reason.
  std::string expectBadInput(const std::string& args) const {
    const CliRun r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\nstderr: " << r.err;
    EXPECT_EQ(r.err.rfind(kPrefix, 0), 0u) << "stderr: " << r.err;
    EXPECT_FALSE(r.err.empty());
    if (!r.err.empty()) {
      EXPECT_EQ(r.err.back(), '\n');
      EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
    }
    EXPECT_GT(r.err.size(), std::string(kPrefix).size() + 5) << "no reason given";
    return r.err;
  }

  // Every map these tests read is shipped with the repository: a missing one is a failure.
  static void requireMap(const std::string& path) { ASSERT_TRUE(fs::exists(path)) << "map not found: " << path; }

  fs::path dir_;
};

bool neighbours(const json& a, const json& b) {
  const int dr = std::abs(a[0].get<int>() - b[0].get<int>()), dc = std::abs(a[1].get<int>() - b[1].get<int>());
  return std::max(dr, dc) == 1;
}

double recomputedLength(const json& path) {
  double length = 0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const bool diagonal = path[k][0] != path[k - 1][0] && path[k][1] != path[k - 1][1];
    length += diagonal ? std::sqrt(2.0) : 1.0;
  }
  return length;
}

// A paper map's optima (maps/paper/paper_maps.json).
eaci::paper::PaperMap optimum(const std::string& name) { return eaci::paper::paperMapNamed(eaci::test::mapsDir(), name); }

// A* lengths of the paper maps.
struct AStarCase {
  const char* map;
  const char* start;
  const char* goal;
  bool corner_cutting;
  double length;
};

TEST_F(CliTest, AStarReproducesPaperOptima) {
  const AStarCase cases[] = {
      {"paper-20x20.txt", "0,0", "19,19", true, optimum("paper-20x20").optimum_corner_cutting},
      {"paper-20x20.txt", "0,0", "19,19", false, optimum("paper-20x20").optimum_no_corner_cutting},
      {"paper-30x30.txt", "29,0", "0,29", true, optimum("paper-30x30").optimum_corner_cutting},
      {"paper-40x40.txt", "0,0", "39,39", true, optimum("paper-40x40").optimum_corner_cutting},
  };
  for (const AStarCase& c : cases) {
    SCOPED_TRACE(std::string(c.map) + (c.corner_cutting ? " corner cutting" : " no corner cutting"));
    const std::string map = paperMap(c.map);
    ASSERT_NO_FATAL_FAILURE(requireMap(map));
    CliRun r;
    const json j = runJson("--map " + quote(map) + " --start " + c.start + " --goal " + c.goal +
                               " --algorithm astar --set allow_corner_cutting=" + (c.corner_cutting ? "true" : "false"),
                           &r);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(j.value("success", false));
    EXPECT_EQ(j["algorithm"], "astar");
    EXPECT_NEAR(j["length"].get<double>(), c.length, 1e-3);
    EXPECT_EQ(j["cost"].get<double>(), j["length"].get<double>());  // no costs on a map file: cost = length
    EXPECT_NEAR(j["length_m"].get<double>(), c.length, 1e-3);  // resolution 1
    EXPECT_NEAR(recomputedLength(j["path"]), c.length, 1e-3);
    EXPECT_NE(r.out.find("astar"), std::string::npos) << r.out;
  }
}

TEST_F(CliTest, NoPathExitsThree) {
  const std::string map = paperMap("paper-40x40.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  for (const char* algorithm : {"astar", "eaci"}) {
    SCOPED_TRACE(algorithm);
    CliRun r;
    const json j = runJson("--map " + quote(map) + " --start 0,0 --goal 39,39 --algorithm " + algorithm +
                               " --set allow_corner_cutting=false --set max_iterations=5",
                           &r);
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_EQ(j.value("outcome", std::string()), "no_path");
    EXPECT_EQ(r.err.rfind(kPrefix, 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    EXPECT_EQ(j.value("success", true), false);
    EXPECT_TRUE(j.contains("error") && j["error"].is_string() && !j["error"].get<std::string>().empty());
    EXPECT_TRUE(j["length"].is_null());
    EXPECT_EQ(j["algorithm"], algorithm);
  }
}

TEST_F(CliTest, SerialNumbersEqualRowCol) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  const std::string common = "--map " + quote(map) + " --algorithm astar --set allow_corner_cutting=true";
  CliRun a, b;
  const json by_serial = runJson(common + " --start-cell 1 --goal-cell 400", &a);
  const json by_cell = runJson(common + " --start 0,0 --goal 19,19", &b);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(by_serial["start"], json::array({0, 0}));
  EXPECT_EQ(by_serial["goal"], json::array({19, 19}));
  EXPECT_EQ(by_serial["path"], by_cell["path"]);
  EXPECT_DOUBLE_EQ(by_serial["length"].get<double>(), by_cell["length"].get<double>());
}

TEST_F(CliTest, EaciReturnsAConnectedPath) {
  const std::string map_file = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map_file));
  CliRun r;
  const json j = runJson("--map " + quote(map_file) + " --start 0,0 --goal 19,19 --set max_iterations=20 --seed 3", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(j["success"].get<bool>());
  EXPECT_FALSE(j.contains("error"));
  EXPECT_EQ(j["algorithm"], "eaci");
  const json& path = j["path"];
  ASSERT_GE(path.size(), 2u);
  EXPECT_EQ(path.front(), json::array({0, 0}));
  EXPECT_EQ(path.back(), json::array({19, 19}));
  const eaci::OccupancyMap map = eaci::loadMap(map_file);
  for (std::size_t k = 0; k < path.size(); ++k) {
    const int row = path[k][0], col = path[k][1];
    EXPECT_EQ(map.cells[static_cast<std::size_t>(row) * map.width + col], eaci::kFreeValue) << "cell " << k;
    if (k > 0) {
      EXPECT_TRUE(neighbours(path[k - 1], path[k])) << "step " << k;
    }
  }
  EXPECT_NEAR(j["length"].get<double>(), recomputedLength(path), 1e-9);
  EXPECT_GE(j["length"].get<double>(), optimum("paper-20x20").optimum_no_corner_cutting - 1e-3);  // never shorter than the optimum
  ASSERT_EQ(j["path_xy"].size(), path.size());
  EXPECT_DOUBLE_EQ(j["path_xy"][0][0].get<double>(), 0.5);   // centre of (0, 0) on a 20-row map
  EXPECT_DOUBLE_EQ(j["path_xy"][0][1].get<double>(), 19.5);

  // The report's bookkeeping.
  EXPECT_EQ(j["iterations_run"], 20);
  EXPECT_EQ(j["seed"], 3);
  EXPECT_EQ(j["parameters"]["seed"], 3);
  EXPECT_EQ(j["parameters"]["max_iterations"], 20);
  EXPECT_EQ(j["lost_ants_per_iteration"].size(), 20u);
  EXPECT_EQ(j["best_cost_per_iteration"].size(), 20u);
  EXPECT_EQ(j["best_cost_so_far"].size(), 20u);
  // The keys' names before the cost model stay for one release, with the same values.
  EXPECT_EQ(j["best_length_per_iteration"], j["best_cost_per_iteration"]);
  EXPECT_EQ(j["best_length_so_far"], j["best_cost_so_far"]);
  long long lost = 0;
  for (const auto& v : j["lost_ants_per_iteration"]) lost += v.get<long long>();
  EXPECT_EQ(j["lost_ants_total"].get<long long>(), lost);
  // iterations_to_converge is the iteration at which the final best length was first reached
  // (the paper's "average iterative times", docs: spec section 3.7): the best so far equals the
  // route's length there and is longer one iteration before.
  const int converged = j["iterations_to_converge"].get<int>();
  ASSERT_GE(converged, 1);
  ASSERT_LE(converged, 20);
  const json& best_so_far = j["best_cost_so_far"];  // a binary map: cost = length
  EXPECT_NEAR(best_so_far[converged - 1].get<double>(), j["length"].get<double>(), 1e-9);
  if (converged > 1 && !best_so_far[converged - 2].is_null()) {  // null: no route yet
    EXPECT_GT(best_so_far[converged - 2].get<double>(), j["length"].get<double>() + 1e-9);
  }
  EXPECT_NEAR(j["best_cost_so_far"].back().get<double>(), j["length"].get<double>(), 1e-9);
  for (const auto& v : j["best_cost_per_iteration"]) EXPECT_TRUE(v.is_null() || v.is_number());
  ASSERT_GE(j["islands"].size(), 2u);
  EXPECT_EQ(j["islands"].front(), json::array({0, 0}));
  EXPECT_EQ(j["islands"].back(), json::array({19, 19}));
  EXPECT_TRUE(j["total_turn_deg"].is_number());
  EXPECT_TRUE(j["time_ms"].is_number());
  EXPECT_EQ(j["map"]["width"], 20);
  EXPECT_EQ(j["map"]["height"], 20);
  EXPECT_DOUBLE_EQ(j["map"]["resolution"].get<double>(), 1.0);
  EXPECT_EQ(j["start"], json::array({0, 0}));
  EXPECT_EQ(j["goal"], json::array({19, 19}));
  for (const std::string& name : eaci::parameterNames())
    EXPECT_TRUE(j["parameters"].contains(name) && !j["parameters"][name].is_null()) << name;
}

// --turn-cost: astar minimises cost + turn_cost x turn; the report gives both and the angle.
TEST_F(CliTest, TurnCostPricesTheCornersOfAStarRoutes) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  const std::string args = "--map " + quote(map) + " --start 0,0 --goal 19,19 --algorithm astar --set allow_corner_cutting=true";
  const auto routeOf = [this](const std::string& arguments) {  // a route, or a failure
    CliRun r;
    const json report = runJson(arguments, &r);
    EXPECT_EQ(r.exit_code, 0) << arguments << "\n" << r.err;
    return report;
  };
  constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
  const json plain = routeOf(args), turning = routeOf(args + " --turn-cost 0.5");
  EXPECT_EQ(plain["combined_cost"], plain["cost"]);
  EXPECT_EQ(turning["parameters"]["turn_cost"], 0.5);
  EXPECT_NEAR(turning["combined_cost"].get<double>(),
              turning["cost"].get<double>() + 0.5 * turning["total_turn_deg"].get<double>() * kRadiansPerDegree, 1e-9);
  // Cheaper under the combined objective than the shortest route, which turns more.
  EXPECT_LT(turning["total_turn_deg"].get<double>(), plain["total_turn_deg"].get<double>());
  EXPECT_LT(turning["combined_cost"].get<double>(),
            plain["cost"].get<double>() + 0.5 * plain["total_turn_deg"].get<double>() * kRadiansPerDegree);
  EXPECT_NE(expectBadInput(args + " --turn-cost -1").find("turn_cost must be a number in [0, 1e6]"), std::string::npos);
  EXPECT_NE(expectBadInput(args + " --turn-cost nan").find("turn_cost"), std::string::npos);
}

// --start-yaw, --goal-yaw: the turns onto the route and off it are priced too. The test reads
// the first and last moves off the route and measures their angles to the headings itself.
TEST_F(CliTest, StartAndGoalYawsPriceTheTurnsAtTheRoutesEnds) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  const std::string args =
      "--map " + quote(map) + " --start 0,0 --goal 19,19 --algorithm astar --set allow_corner_cutting=true --turn-cost 0.5";
  constexpr double kPi = 3.14159265358979323846;
  CliRun r;
  const json j = runJson(args + " --start-yaw 90 --goal-yaw -135", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json& path = j["path"];
  ASSERT_GE(path.size(), 2u);
  // The angle of the move a -> b (rows down, so north is row - 1) to a heading in degrees.
  const auto turn = [&](const json& a, const json& b, double heading_deg) {
    const double move = std::atan2(-(b[0].get<double>() - a[0].get<double>()), b[1].get<double>() - a[1].get<double>());
    return std::abs(std::remainder(move - heading_deg * kPi / 180.0, 2 * kPi));
  };
  const double ends = turn(path[0], path[1], 90.0) + turn(path[path.size() - 2], path.back(), -135.0);
  EXPECT_GT(ends, 0.0);  // from the top left, facing north, to the bottom right, facing south-west: both turn
  EXPECT_NEAR(j["combined_cost"].get<double>(),
              j["cost"].get<double>() + 0.5 * (j["total_turn_deg"].get<double>() * kPi / 180.0 + ends), 1e-9);
  EXPECT_NE(expectBadInput(args + " --goal-yaw 400").find("--goal-yaw"), std::string::npos);
}

TEST_F(CliTest, SameSeedSameRoute) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  const std::string args = "--map " + quote(map) + " --start 0,0 --goal 19,19 --set max_iterations=10 --set seed=5 --seed 9";
  CliRun a, b;
  const json first = runJson(args, &a);
  const json second = runJson(args, &b);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(first["seed"], 9);  // --seed wins over --set seed
  EXPECT_EQ(first["path"], second["path"]);
  EXPECT_EQ(first["lost_ants_per_iteration"], second["lost_ants_per_iteration"]);
}

TEST_F(CliTest, ClassicAcoFindsAPath) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  CliRun r;
  const json j = runJson("--map " + quote(map) + " --start 0,0 --goal 19,19 --algorithm aco --set max_iterations=20 "
                         "--set allow_corner_cutting=true",
                         &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["algorithm"], "aco");
  EXPECT_EQ(j["path"].front(), json::array({0, 0}));
  EXPECT_EQ(j["path"].back(), json::array({19, 19}));
  EXPECT_GE(j["length"].get<double>(), optimum("paper-20x20").optimum_corner_cutting - 1e-3);
}

TEST_F(CliTest, ParamsFileThenSetThenSeed) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  writeFile(tmp("params.yaml"), "# tuned\nants: 7\nmax_iterations: 4\nallow_corner_cutting: true\nseed: 11\n");
  CliRun r;
  json j = runJson("--map " + quote(map) + " --start 0,0 --goal 19,19 --params " + quote(tmp("params.yaml").string()), &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["parameters"]["ants"], 7);
  EXPECT_EQ(j["parameters"]["max_iterations"], 4);
  EXPECT_EQ(j["parameters"]["allow_corner_cutting"], true);
  EXPECT_EQ(j["iterations_run"], 4);
  EXPECT_EQ(j["seed"], 11);
  j = runJson("--map " + quote(map) + " --start 0,0 --goal 19,19 --params " + quote(tmp("params.yaml").string()) +
                  " --set ants=6 --set ants=5 --seed 12",
              &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["parameters"]["ants"], 5);  // the last --set wins
  EXPECT_EQ(j["parameters"]["max_iterations"], 4);
  EXPECT_EQ(j["seed"], 12);
}

TEST_F(CliTest, CostModelParametersAndUnknownCellsAreParameters) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  const std::string common = "--map " + quote(map) + " --start 0,0 --goal 19,19 --algorithm astar";
  CliRun r;
  json j = runJson(common + " --set cost_factor=1.5 --set neutral_cost=20 --set lethal_cost=200", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["parameters"]["cost_factor"], 1.5);
  EXPECT_EQ(j["parameters"]["neutral_cost"], 20.0);
  EXPECT_EQ(j["parameters"]["lethal_cost"], 200);
  EXPECT_EQ(j["parameters"]["allow_unknown"], false);
  EXPECT_EQ(j["unknown"], "obstacle");
  for (const char* word : {"expensive", "free"}) {  // --unknown is allow_unknown; free is the old word
    j = runJson(common + " --unknown " + word, &r);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(j["parameters"]["allow_unknown"], true) << word;
    EXPECT_EQ(j["unknown"], "expensive") << word;
  }
  j = runJson(common + " --set allow_unknown=true", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["unknown"], "expensive");
  runJson(common + " --set cost_factor=-1", &r);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cost_factor must be a number in [0, 1e6]"), std::string::npos) << r.err;
}

TEST_F(CliTest, BadInputExitsTwoWithOneLine) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  const std::string m = "--map " + quote(map);
  const std::string ok = m + " --start 0,0 --goal 19,19";
  EXPECT_NE(expectBadInput("--map " + quote(tmp("missing.txt").string()) + " --start 0,0 --goal 1,1").find("missing.txt"),
            std::string::npos);
  EXPECT_NE(expectBadInput(m + " --start 0,6 --goal 19,19").find("obstacle"), std::string::npos);
  EXPECT_NE(expectBadInput(m + " --start 20,0 --goal 19,19").find("off the map"), std::string::npos);
  expectBadInput(m + " --start -1,0 --goal 19,19");
  expectBadInput(m + " --start 0,0 --goal 19,19,4");
  expectBadInput(m + " --start zero,0 --goal 19,19");
  expectBadInput(m + " --start-cell 0 --goal-cell 400");
  expectBadInput(m + " --start-cell 1 --goal-cell 401");
  expectBadInput(m + " --start-xy 25,1 --goal 19,19");
  EXPECT_NE(expectBadInput(ok + " --set nosuchkey=1").find("nosuchkey"), std::string::npos);
  EXPECT_NE(expectBadInput(ok + " --set ants=0").find("ants"), std::string::npos);
  EXPECT_NE(expectBadInput(ok + " --set alpha=nan").find("alpha"), std::string::npos);
  expectBadInput(ok + " --set alpha=abc");
  expectBadInput(ok + " --set alpha");
  expectBadInput(ok + " --seed -3");
  expectBadInput(m + " --start 0,0");                                 // no goal
  expectBadInput(m + " --goal 19,19");                                // no start
  expectBadInput(m + " --start 0,0 --start-cell 1 --goal 19,19");     // start twice
  expectBadInput(m + " --start 0,0 --goal 19,19 --goal-xy 1,1");      // goal twice
  expectBadInput("--start 0,0 --goal 19,19");                         // no map
  expectBadInput(ok + " --algorithm dijkstra");
  expectBadInput(ok + " --unknown maybe");
  expectBadInput(ok + " --no-such-option");
  expectBadInput(ok + " stray");
}

TEST_F(CliTest, BadParamsFilesExitTwo) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  const std::string ok = "--map " + quote(map) + " --start 0,0 --goal 19,19 --params ";
  writeFile(tmp("unknown.yaml"), "ants: 10\nnot_a_parameter: 3\n");
  EXPECT_NE(expectBadInput(ok + quote(tmp("unknown.yaml").string())).find("not_a_parameter"), std::string::npos);
  writeFile(tmp("broken.yaml"), "ants: [1, 2\nbeta: {\n");
  expectBadInput(ok + quote(tmp("broken.yaml").string()));
  writeFile(tmp("scalar.yaml"), "just some words\n");
  expectBadInput(ok + quote(tmp("scalar.yaml").string()));
  writeFile(tmp("list.yaml"), "- ants\n- 10\n");
  expectBadInput(ok + quote(tmp("list.yaml").string()));
  writeFile(tmp("nested.yaml"), "eaci_planner:\n  ants: 10\n");
  expectBadInput(ok + quote(tmp("nested.yaml").string()));
  writeFile(tmp("badvalue.yaml"), "ants: many\n");
  expectBadInput(ok + quote(tmp("badvalue.yaml").string()));
  writeFile(tmp("invalid.yaml"), "kappa: 5\n");
  expectBadInput(ok + quote(tmp("invalid.yaml").string()));
  expectBadInput(ok + quote(tmp("does-not-exist.yaml").string()));
}

TEST_F(CliTest, JsonIsWrittenOnBadInput) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  CliRun r;
  const json j = runJson("--map " + quote(map) + " --start 0,6 --goal 19,19 --algorithm aco", &r);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(j.value("success", true), false);
  EXPECT_EQ(j.value("outcome", std::string()), "start_blocked");
  EXPECT_EQ(j.value("status", std::string()), "start_blocked");
  EXPECT_FALSE(j.value("error", std::string()).empty());
  EXPECT_EQ(j["algorithm"], "aco");
  EXPECT_TRUE(j["length"].is_null());
}

// The JSON's "outcome" names why a run ended, in a stable word, whatever stage refused it;
// the exit status is 2 for every refusal of the input.
TEST_F(CliTest, TheOutcomeWordNamesEveryEnding) {
  const std::string map = paperMap("paper-20x20.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  const std::string m = "--map " + quote(map);
  struct Case {
    std::string args;
    const char* outcome;
    int exit_code;
  };
  for (const Case& c : {Case{m + " --start 0,0 --goal 19,19", "ok", 0},
                        Case{m + " --start 20,0 --goal 19,19", "start_off_map", 2},
                        Case{m + " --start-xy 25,1 --goal 19,19", "start_off_map", 2},
                        Case{m + " --start 0,0 --goal-cell 401", "goal_off_map", 2},
                        Case{m + " --start 0,0 --goal 0,6", "goal_blocked", 2},
                        Case{m + " --start 0,0 --goal 0,6 --tolerance 0", "goal_blocked", 2},
                        Case{m + " --start 0,0 --goal 19,19 --set ants=0", "invalid_parameters", 2},
                        Case{"--map " + quote(tmp("missing.txt").string()) + " --start 0,0 --goal 1,1", "invalid_map", 2},
                        Case{m + " --start 0,0", "bad_input", 2}}) {
    SCOPED_TRACE(c.args);
    CliRun r;
    const json j = runJson(c.args, &r);
    EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
    EXPECT_EQ(j.value("outcome", std::string()), c.outcome);
  }
}

TEST_F(CliTest, HelpExitsZero) {
  const CliRun r = run("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option : {"--map", "--start-cell", "--goal-xy", "--params", "--set", "--json", "--png", "--unknown"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

TEST_F(CliTest, PngIsWritten) {
  const std::string map = paperMap("paper-40x40.txt");
  ASSERT_NO_FATAL_FAILURE(requireMap(map));
  const fs::path png = tmp("plan.png");
  const CliRun r = run("--map " + quote(map) + " --start 0,0 --goal 39,39 --set allow_corner_cutting=true "
                    "--set max_iterations=10 --png " + quote(png.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(png.string()), std::string::npos) << r.out;
  const std::string bytes = readFile(png);
  ASSERT_GT(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  auto be32 = [&](std::size_t at) {
    return (std::uint32_t(std::uint8_t(bytes[at])) << 24) | (std::uint32_t(std::uint8_t(bytes[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(bytes[at + 2])) << 8) | std::uint32_t(std::uint8_t(bytes[at + 3]));
  };
  EXPECT_GE(be32(16), 40u * 24u);  // IHDR width: 24 px per cell on a 40 x 40 map, plus margins
  EXPECT_GE(be32(20), 40u * 24u);

  // A* pictures too, and an unwritable PNG is bad input.
  const CliRun astar = run("--map " + quote(map) + " --start 0,0 --goal 39,39 --set allow_corner_cutting=true "
                        "--algorithm astar -q --png " + quote(tmp("astar.png").string()));
  EXPECT_EQ(astar.exit_code, 0) << astar.err;
  EXPECT_TRUE(astar.out.empty()) << "--quiet printed: " << astar.out;
  EXPECT_TRUE(fs::exists(tmp("astar.png")));
  expectBadInput("--map " + quote(map) + " --start 0,0 --goal 39,39 --set allow_corner_cutting=true "
                 "--algorithm astar --png " + quote((dir_ / "no-such-dir" / "x.png").string()));
}

// The summary names both routes and the picture draws the smoothed one. On a free 3 x 10 map
// A*'s route from (0, 0) to (2, 9) takes 7 straight and 2 diagonal steps (7 + 2 sqrt 2 =
// 9.8284 cells); smoothed, it is one straight segment of sqrt(2^2 + 9^2) = 9.2195 cells that
// turns nowhere.
TEST_F(CliTest, SummaryAndPictureShowTheGridAndTheSmoothedRoute) {
  writeFile(tmp("free.txt"), "0 0 0 0 0 0 0 0 0 0\n0 0 0 0 0 0 0 0 0 0\n0 0 0 0 0 0 0 0 0 0\n");
  const std::string common = "--map " + quote(tmp("free.txt").string()) + " --start 0,0 --goal 2,9 --algorithm astar";
  const CliRun smoothed = run(common + " --set smooth_path=true --png " + quote(tmp("smoothed.png").string()));
  ASSERT_EQ(smoothed.exit_code, 0) << smoothed.err;
  EXPECT_NE(smoothed.out.find("grid route:     length 9.8284 cells = 9.8284 m, total turn "), std::string::npos)
      << smoothed.out;
  EXPECT_NE(smoothed.out.find("smoothed route: length 9.2195 cells = 9.2195 m, total turn 0 deg (2 corners"),
            std::string::npos)
      << smoothed.out;
  const CliRun plain = run(common + " --png " + quote(tmp("plain.png").string()));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_NE(plain.out.find("grid route:     length 9.8284 cells"), std::string::npos) << plain.out;
  EXPECT_NE(plain.out.find("smoothed route: off"), std::string::npos) << plain.out;

  // The smoothed route's colour is in the smoothed picture only.
  auto smoothed_pixels = [](const fs::path& png) {
    const auto colour = eaci::tools::kSmoothedRouteColour;
    int w = 0, h = 0, channels = 0;
    unsigned char* rgb = stbi_load(png.c_str(), &w, &h, &channels, 3);
    if (rgb == nullptr) return -1;
    int n = 0;
    for (int i = 0; i < w * h; ++i)
      n += rgb[3 * i] == colour[0] && rgb[3 * i + 1] == colour[1] && rgb[3 * i + 2] == colour[2] ? 1 : 0;
    stbi_image_free(rgb);
    return n;
  };
  EXPECT_GT(smoothed_pixels(tmp("smoothed.png")), 9 * 24);  // at least a pixel row along 9 cells of 24 px
  EXPECT_EQ(smoothed_pixels(tmp("plain.png")), 0);
}

TEST_F(CliTest, JsonHasClearanceAndMeanCellCost) {
  // A wall along row 0 and one block at (4, 3); A* from (2, 0) to (2, 6) runs straight along
  // row 2: 2 cells from the wall and from the block, resolution 1 (a .txt matrix).
  writeFile(tmp("wall.txt"),
            "1 1 1 1 1 1 1\n"
            "0 0 0 0 0 0 0\n"
            "0 0 0 0 0 0 0\n"
            "0 0 0 0 0 0 0\n"
            "0 0 0 1 0 0 0\n");
  CliRun r;
  const json j = runJson("--map " + quote(tmp("wall.txt").string()) + " --start 2,0 --goal 2,6 --algorithm astar", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(j["path"].size(), 7u);
  EXPECT_DOUBLE_EQ(j["min_clearance_m"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["smoothed_min_clearance_m"].get<double>(), 2.0);  // unsmoothed: the same cells' lines
  EXPECT_DOUBLE_EQ(j["mean_cell_cost"].get<double>(), 0.0);  // a map file has no graded costs

  // Along row 1 the route is next to the wall.
  const json near = runJson("--map " + quote(tmp("wall.txt").string()) + " --start 1,0 --goal 1,6 --algorithm astar", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_DOUBLE_EQ(near["min_clearance_m"].get<double>(), 1.0);

  // No obstacle anywhere: no clearance to report. A failed plan: both null.
  writeFile(tmp("open.txt"), "0 0 0\n0 0 0\n");
  const json open = runJson("--map " + quote(tmp("open.txt").string()) + " --start 0,0 --goal 1,2 --algorithm astar", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(open["min_clearance_m"].is_null());
  EXPECT_DOUBLE_EQ(open["mean_cell_cost"].get<double>(), 0.0);
  const json failed = runJson("--map " + quote(tmp("wall.txt").string()) + " --start 0,0 --goal 2,6 --algorithm astar", &r);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(failed["min_clearance_m"].is_null());
  EXPECT_TRUE(failed["smoothed_min_clearance_m"].is_null());
  EXPECT_TRUE(failed["mean_cell_cost"].is_null());
}

TEST_F(CliTest, ClearanceInMetresOnAYamlMap) {
  // 6 x 6 map, 0.5 m cells, one occupied cell at (0, 0); A* from (5, 0) to (5, 5) along the
  // bottom row is 5 cells = 2.5 m from it at best.
  std::string pgm = "P5\n6 6\n255\n";
  std::string cells(36, static_cast<char>(254));
  cells[0] = 0;
  pgm += cells;
  writeFile(tmp("dot.pgm"), pgm);
  writeFile(tmp("dot.yaml"),
            "image: dot.pgm\nresolution: 0.5\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  CliRun r;
  const json j = runJson("--map " + quote(tmp("dot.yaml").string()) + " --start 5,0 --goal 5,5 --algorithm astar", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_DOUBLE_EQ(j["min_clearance_m"].get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(j["mean_cell_cost"].get<double>(), 0.0);
}

TEST_F(CliTest, UnknownCellsArePassableAtTheDearestCost) {
  // A 5 x 1 corridor whose middle pixel is grey (occupancy 0.5: unknown in trinary mode).
  // --unknown obstacle: no route; --unknown expensive (or free): straight through, four moves,
  // one into the unknown cell at 1 x (50 + 3 x 252) / 50 = 16.12, three at 1.
  std::string pgm = "P5\n5 1\n255\n";
  std::string cells(5, static_cast<char>(254));
  cells[2] = static_cast<char>(128);
  pgm += cells;
  writeFile(tmp("corridor.pgm"), pgm);
  writeFile(tmp("corridor.yaml"),
            "image: corridor.pgm\nresolution: 1.0\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const std::string m = "--map " + quote(tmp("corridor.yaml").string()) + " --start 0,0 --goal 0,4 --algorithm astar";
  CliRun r;
  runJson(m + " --unknown obstacle", &r);
  EXPECT_EQ(r.exit_code, 3) << r.err;  // no route
  for (const char* word : {"expensive", "free"}) {
    const json j = runJson(m + " --unknown " + word, &r);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NEAR(j["cost"].get<double>(), 3.0 + 806.0 / 50.0, 1e-9) << word;
    EXPECT_NEAR(j["length"].get<double>(), 4.0, 1e-9) << word;
  }
}

TEST_F(CliTest, ToleranceEndsOnTheNearestCellTheStartCanReach) {
  // Columns 4 and 5 wall the right part off. Goal (2, 5) in the wall: (2, 6) right behind it
  // is free and 1 away but unreachable; (2, 3), 2 away, is the nearest cell the start reaches.
  const std::string row = "0 0 0 0 1 1 0 0 0 0\n";
  writeFile(tmp("walled.txt"), row + row + row + row + row);
  const std::string m = "--map " + quote(tmp("walled.txt").string()) + " --start 2,0 --algorithm astar";
  CliRun r;
  const json j = runJson(m + " --goal 2,5 --tolerance 2", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["goal"], json::array({2, 3}));
  EXPECT_EQ(j["requested_goal"], json::array({2, 5}));
  EXPECT_NEAR(j["length"].get<double>(), 3.0, 1e-9);
  // A free goal behind the wall: (2, 3) is 5 away from (2, 8).
  const json behind = runJson(m + " --goal 2,8 --tolerance 5", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(behind["goal"], json::array({2, 3}));
}

TEST_F(CliTest, StartXyOnYamlMap) {
  // 10 x 10 free map, 0.5 m cells, origin (-1, -1): x and y run from -1 to 4 m.
  std::string pgm = "P5\n10 10\n255\n";
  pgm += std::string(100, static_cast<char>(254));
  writeFile(tmp("small.pgm"), pgm);
  writeFile(tmp("small.yaml"),
            "image: small.pgm\nresolution: 0.5\norigin: [-1.0, -1.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const std::string m = "--map " + quote(tmp("small.yaml").string());
  CliRun r;
  const json j = runJson(m + " --start-xy -0.9,-0.9 --goal-xy 3.9,3.9 --algorithm astar", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["start"], json::array({9, 0}));
  EXPECT_EQ(j["goal"], json::array({0, 9}));
  EXPECT_NEAR(j["length"].get<double>(), 9 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(j["length_m"].get<double>(), 4.5 * std::sqrt(2.0), 1e-9);
  EXPECT_DOUBLE_EQ(j["path_xy"].front()[0].get<double>(), -0.75);
  EXPECT_DOUBLE_EQ(j["path_xy"].front()[1].get<double>(), -0.75);
  EXPECT_DOUBLE_EQ(j["path_xy"].back()[0].get<double>(), 3.75);
  EXPECT_DOUBLE_EQ(j["path_xy"].back()[1].get<double>(), 3.75);
  EXPECT_DOUBLE_EQ(j["map"]["resolution"].get<double>(), 0.5);

  const json eaci = runJson(m + " --start-xy=-0.9,-0.9 --goal 0,9 --set max_iterations=10", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(eaci["path"].front(), json::array({9, 0}));

  expectBadInput(m + " --start-xy -1.1,0 --goal 0,9");  // just off the left edge
  expectBadInput(m + " --start-xy 0,4.0 --goal 0,9");   // the top edge belongs to no cell
  expectBadInput(m + " --start-xy nan,0 --goal 0,9");
  expectBadInput(m + " --start-xy 1 --goal 0,9");
}

TEST_F(CliTest, LabMapWithEaci) {
  const std::string lab = std::string(EACI_SOURCE_DIR) + "/maps/lab.yaml";
  ASSERT_NO_FATAL_FAILURE(requireMap(lab));
  CliRun r;
  const json j = runJson("--map " + quote(lab) + " --start-xy 0.4,0.4 --goal-xy 4.4,2.6 --set max_iterations=30 --png " +
                             quote(tmp("lab.png").string()),
                         &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(j["success"].get<bool>());
  EXPECT_EQ(j["start"], json::array({51, 8}));
  EXPECT_EQ(j["goal"], json::array({7, 88}));
  EXPECT_NEAR(j["length_m"].get<double>(), j["length"].get<double>() * 0.05, 1e-9);
  EXPECT_TRUE(fs::exists(tmp("lab.png")));
}

}  // namespace

namespace {

// 5 x 5 map file (resolution 1 m): a 2 x 2 block in the bottom-right corner.
std::string cornerBlockMap() {
  return "0 0 0 0 0\n"
         "0 0 0 0 0\n"
         "0 0 0 0 0\n"
         "0 0 0 1 1\n"
         "0 0 0 1 1\n";
}

// A raw map (map_server mode: raw, each pixel a costmap_2d cost), 7 x 5 cells of 1 m:
//        c0 c1 c2  c3 c4 c5 c6
//   r0:   0  0  0   0  0  0  0
//   r1:   0  0  0 200  0  0  0      a band of cost 200 down column 3,
//   r2:   0  0  0 200  0  0  0      open (cost 0) only in row 0
//   r3:   0  0  0 200  0  0  0
//   r4:   0  0  0 200  0  0  0      start (4, 0), goal (4, 6)
// A move into a cell of cost c costs step x (50 + 3c) / 50 (neutral_cost 50, cost_factor 3).
// By hand: straight along row 4 enters one band cell: 5 + 13 = 18. Over the top through
// (0, 3): 2 x (3 sqrt2 + 1) = 10.485, with no cost paid; every other crossing enters a band
// cell (>= 13). With cost_factor 0 only lengths count: row 4 straight, 6. With lethal_cost 200
// the band is a wall: no diagonal may pass its corners, so the route runs (0, 2) (0, 3) (0, 4)
// straight: 2 x (2 sqrt2 + 2) + 2 = 4 sqrt2 + 6 = 11.657.
TEST_F(CliTest, RawMapRoutesAroundAHighCostBand) {
  std::string pixels;
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 7; ++c) pixels.push_back(static_cast<char>(c == 3 && r > 0 ? 200 : 0));
  writeFile(tmp("band.pgm"), "P5\n7 5\n255\n" + pixels);
  const fs::path yaml = tmp("band.yaml");
  writeFile(yaml, "image: band.pgm\nmode: raw\nresolution: 1\norigin: [0, 0, 0]\nnegate: 0\n"
                  "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const std::string common = "--map " + quote(yaml.string()) + " --start 4,0 --goal 4,6";
  CliRun r;

  const json detour = runJson(common + " --algorithm astar", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(detour["cost"].get<double>(), 6 * std::sqrt(2.0) + 2, 1e-9);
  EXPECT_NEAR(detour["length"].get<double>(), 6 * std::sqrt(2.0) + 2, 1e-9);
  EXPECT_DOUBLE_EQ(detour["mean_cell_cost"].get<double>(), 0.0);
  EXPECT_NE(std::find(detour["path"].begin(), detour["path"].end(), json::array({0, 3})), detour["path"].end())
      << detour["path"].dump();
  const CliRun summary = run(common + " --algorithm astar");
  EXPECT_NE(summary.out.find("costmap costs, obstacles from 253"), std::string::npos) << summary.out;

  const json straight = runJson(common + " --algorithm astar --set cost_factor=0", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_DOUBLE_EQ(straight["length"].get<double>(), 6.0);
  EXPECT_DOUBLE_EQ(straight["cost"].get<double>(), 6.0);
  for (const auto& cell : straight["path"]) EXPECT_EQ(cell[0], 4);
  EXPECT_NEAR(straight["mean_cell_cost"].get<double>(), 200.0 / 7.0, 1e-9);  // 7 cells, one in the band

  const json walled = runJson(common + " --algorithm astar --set lethal_cost=200", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(walled["cost"].get<double>(), 4 * std::sqrt(2.0) + 6, 1e-9);
  for (const json& cell : {json::array({0, 2}), json::array({0, 3}), json::array({0, 4})})
    EXPECT_NE(std::find(walled["path"].begin(), walled["path"].end(), cell), walled["path"].end()) << cell.dump();

  // EACI finds the detour too (its cost is at most A*'s plus a little on such a small map).
  const json eaci = runJson(common + " --algorithm eaci --seed 3", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LT(eaci["cost"].get<double>(), 18.0);
  EXPECT_GE(eaci["cost"].get<double>(), 6 * std::sqrt(2.0) + 2 - 1e-9);

  // The picture of a raw map is written (the costs as a grey ramp).
  ASSERT_EQ(run(common + " --algorithm astar --png " + quote(tmp("band.png").string())).exit_code, 0);
  EXPECT_GT(fs::file_size(tmp("band.png")), 100u);
}

TEST_F(CliTest, UnknownMapModeIsNamed) {
  writeFile(tmp("m.pgm"), "P5\n2 1\n255\n" + std::string(2, '\0'));
  const fs::path yaml = tmp("m.yaml");
  writeFile(yaml, "image: m.pgm\nmode: bogus\nresolution: 1\norigin: [0, 0, 0]\n");
  const std::string reason = expectBadInput("--map " + quote(yaml.string()) + " --start 0,0 --goal 0,1");
  for (const std::string& part : std::vector<std::string>{yaml.string(), "'mode'", "'bogus'"})
    EXPECT_NE(reason.find(part), std::string::npos) << part << " missing from " << reason;
}

}  // namespace

TEST_F(CliTest, ToleranceMovesAGoalInAnObstacleToTheNearestFreeCell) {
  const fs::path map = tmp("block.txt");
  writeFile(map, cornerBlockMap());
  const std::string common = "--map " + quote(map.string()) + " --start 0,0 --goal 4,4 --algorithm astar";
  // (4,4): (3,4) and (4,3) 1 m away and (3,3) 1.41 m are obstacles; (2,4) and (4,2) 2 m away are free.
  const std::string reason = expectBadInput(common + " --tolerance 1.5");
  EXPECT_NE(reason.find("--tolerance 1.5 m"), std::string::npos) << reason;
  EXPECT_NE(reason.find("row 4, col 4"), std::string::npos) << reason;
  CliRun r;
  const json j = runJson(common + " --tolerance 2", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["goal"], json::array({2, 4}));  // of the two, the first in row-major order
  EXPECT_EQ(j["requested_goal"], json::array({4, 4}));
  EXPECT_EQ(j["path"].back(), json::array({2, 4}));
  EXPECT_NE(r.out.find("moved from (row 4, col 4)"), std::string::npos) << r.out;
  // A free goal stays; the report has no requested_goal.
  const json free = runJson("--map " + quote(map.string()) + " --start 0,0 --goal 2,2 --algorithm astar --tolerance 3", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(free["goal"], json::array({2, 2}));
  EXPECT_FALSE(free.contains("requested_goal"));
  // Off the map moves onto it.
  const json off = runJson("--map " + quote(map.string()) + " --start 0,0 --goal -1,2 --algorithm astar --tolerance 1", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(off["goal"], json::array({0, 2}));
  // Without --tolerance the goal in an obstacle is bad input, as before.
  expectBadInput(common);
}

// 5 x 9 map file with a wall along the top row: the straight route runs beside the wall; with
// --inflate 3 --cost-scaling-factor 1 the cells beside it cost 252 e^-1 = 92, two away 34,
// three away 12, and the route swings away from the wall.
TEST_F(CliTest, InflateKeepsRoutesOffWalls) {
  const fs::path map = tmp("wall.txt");
  writeFile(map, "1 1 1 1 1 1 1 1 1\n"
                 "0 0 0 0 0 0 0 0 0\n"
                 "0 0 0 0 0 0 0 0 0\n"
                 "0 0 0 0 0 0 0 0 0\n"
                 "0 0 0 0 0 0 0 0 0\n");
  const std::string common = "--map " + quote(map.string()) + " --start 1,0 --goal 1,8 --algorithm astar";
  CliRun r;
  const json plain = runJson(common, &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_DOUBLE_EQ(plain["length"].get<double>(), 8.0);
  for (const auto& cell : plain["path"]) EXPECT_EQ(cell[0], 1);
  const json inflated = runJson(common + " --inflate 3 --cost-scaling-factor 1", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(inflated["length"].get<double>(), 8.0);
  int farthest = 0;
  for (const auto& cell : inflated["path"]) farthest = std::max(farthest, cell[0].get<int>());
  EXPECT_GE(farthest, 3);
  EXPECT_GT(inflated["cost"].get<double>(), inflated["length"].get<double>());
  // The report measures costs on the inflated cells the route was planned on, clearance from the
  // map's own obstacles: with cost_factor 0 the route stays in row 1, every cell of it 92.
  const json straight = runJson(common + " --inflate 3 --cost-scaling-factor 1 --set cost_factor=0", &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const auto& cell : straight["path"]) EXPECT_EQ(cell[0], 1);
  EXPECT_DOUBLE_EQ(straight["mean_cell_cost"].get<double>(), 92.0);
  EXPECT_DOUBLE_EQ(straight["min_clearance_m"].get<double>(), plain["min_clearance_m"].get<double>());
  EXPECT_DOUBLE_EQ(plain["mean_cell_cost"].get<double>(), 0.0);
  // An inscribed radius of 1 m makes the cells beside the wall obstacles: the start is in one.
  const std::string reason = expectBadInput(common + " --inflate 3 --inscribed-radius 1");
  EXPECT_NE(reason.find("start"), std::string::npos) << reason;
  // ... and --tolerance moves a goal there off it.
  const json moved = runJson("--map " + quote(map.string()) +
                                 " --start 4,0 --goal 1,8 --algorithm astar --inflate 3 --inscribed-radius 1 --tolerance 1",
                             &r);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(moved["goal"], json::array({2, 8}));
  EXPECT_EQ(moved["requested_goal"], json::array({1, 8}));
}

TEST_F(CliTest, BadToleranceAndInflationValuesAreNamed) {
  const fs::path map = tmp("block.txt");
  writeFile(map, cornerBlockMap());
  const std::string common = "--map " + quote(map.string()) + " --start 0,0 --goal 2,2 --algorithm astar";
  struct Case {
    const char* args;
    const char* expected;
  };
  const Case cases[] = {
      {"--tolerance -1", "--tolerance: '-1' is not a number >= 0"},
      {"--tolerance nan", "--tolerance: 'nan' is not a number >= 0"},
      {"--tolerance inf", "--tolerance: 'inf' is not a number >= 0"},
      {"--tolerance 1m", "--tolerance: '1m' is not a number >= 0"},
      {"--inflate -0.5", "--inflate: '-0.5' is not a number >= 0"},
      {"--inflate nan", "--inflate: 'nan' is not a number >= 0"},
      {"--inflate 1 --cost-scaling-factor nan", "--cost-scaling-factor: 'nan' is not a number >= 0"},
      {"--inflate 1 --cost-scaling-factor -3", "--cost-scaling-factor: '-3' is not a number >= 0"},
      {"--inflate 1 --inscribed-radius -1", "--inscribed-radius: '-1' is not a number >= 0"},
      {"--inflate 1 --inscribed-radius 2", "--inscribed-radius 2 m exceeds --inflate 1 m"},
      {"--inscribed-radius 0.2", "--inscribed-radius needs --inflate"},
      {"--cost-scaling-factor 3", "--cost-scaling-factor needs --inflate"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const std::string reason = expectBadInput(common + " " + c.args);
    EXPECT_NE(reason.find(c.expected), std::string::npos) << reason;
  }
}
