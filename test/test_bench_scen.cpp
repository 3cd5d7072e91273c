// Runs the built eaci_bench binary's `scen` command (and eaci_plan) on the hand-made MovingAI
// map test/data/movingai/wall.map and its scenario wall.scen, and checks its records (their
// schema, src/bench/record.hpp) and the lengths against optima worked out by hand; a missing
// binary fails.
//
// wall.map (x = column 0..7, y = row 0..5; '@' and 'T' blocked, '.' and 'G' passable):
//
//     y0  ........
//     y1  ........
//     y2  @@@.@@@@     a wall with a one-cell gap at x 3
//     y3  ........
//     y4  ..TT....     two trees at (2,4) and (3,4)
//     y5  G.......
//
// Without corner cutting the gap (3,2) is entered from (3,1) and left to (3,3) straight: the
// diagonals into it would pass the wall cells (2,2) / (4,2) corner to corner.
//   1. (0,0) -> (7,0): along row 0                                       = 7
//   2. (6,1) -> (1,3): (6,1)-(3,1) 3, gap 2, (3,3)-(1,3) 2                = 7
//   3. (1,5) -> (4,3): every 2-diagonal route passes a tree corner to corner; around it by
//      (1,4),(1,3) then along row 3, or by (4,5),(4,4): 1+1+3 = 2+1+1+1  = 5
//      (with corner cutting (1,4)->(2,3) is allowed: 1 + √2 + 2 = 3 + √2 = 4.41421356)
//   4. (0,0) -> (0,5): (0,0)-(3,1) octile 2+√2, gap 2; (3,3)-(0,5): (2,4) is a tree, so
//      (2,3),(1,3) then (0,4) diagonal and (0,5): 3+√2.  Total 7 + 2√2     = 9.82842712
//   5. (0,3) -> (7,5): along row 3 to (5,3), diagonals (6,4),(7,5): the octile distance
//      5 + 2√2, no obstacle in the way                                   = 7.82842712
//   6. (7,0) -> (7,5): (7,0)-(3,1) octile 3+√2, gap 2, (3,3)-(7,5) octile 2+2√2 by
//      (4,3),(5,3),(6,4),(7,5).  Total 7 + 3√2                            = 11.24264069
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kBench = EACI_BINARY_DIR "/bin/eaci_bench";
const std::string kPlan = EACI_BINARY_DIR "/bin/eaci_plan";
const std::string kData = EACI_SOURCE_DIR "/test/data/movingai";

const double kRoot2 = std::sqrt(2.0);
// The hand-computed optima of wall.scen's six problems, in file order (see above).
const std::vector<double> kOptima = {7.0, 7.0, 5.0, 7.0 + 2 * kRoot2, 5.0 + 2 * kRoot2, 7.0 + 3 * kRoot2};

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

class ScenTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("eaci_scen_" + std::string(info->name()) + "_" + std::to_string(static_cast<long>(::getpid())));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    ASSERT_TRUE(fs::exists(kBench)) << "eaci_bench not built: " << kBench;
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  // Runs `binary args`, returns the exit status; stdout and stderr in out_ / err_.
  int run(const std::string& binary, const std::string& args) {
    const std::string command = quote(binary) + " " + args + " >" + quote((dir_ / "out.txt").string()) + " 2>" +
                                quote((dir_ / "err.txt").string());
    const int status = std::system(command.c_str());
    out_ = readFile(dir_ / "out.txt");
    err_ = readFile(dir_ / "err.txt");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  // The scen command's records (report/scen.jsonl), one per plan, each checked against the schema.
  std::vector<json> runScen(const std::string& scen, const std::string& extra, int expected_status = 0) {
    const int status = run(kBench, "scen " + quote(scen) + " --out " + quote((dir_ / "report").string()) + " " + extra);
    EXPECT_EQ(status, expected_status) << err_;
    std::ifstream in(dir_ / "report" / "scen.jsonl");
    EXPECT_TRUE(in.good()) << "no records: " << err_;
    std::vector<json> records;
    for (std::string line; std::getline(in, line);) {
      records.push_back(json::parse(line));
      const json& r = records.back();
      for (const char* key : {"command", "map", "variant", "seed", "problem", "parameters", "run", "extra", "provenance"})
        EXPECT_TRUE(r.contains(key)) << key << " missing in " << line;
      EXPECT_EQ(r["command"], "scen");
      EXPECT_EQ(r["map"], "wall.map");
      for (const char* key : {"success", "length", "cost", "iterations_to_converge", "lost_ants_total", "time_ms"})
        EXPECT_TRUE(r["run"].contains(key)) << key;
      EXPECT_GE(r["seed"].get<int>(), 1);
      EXPECT_EQ(r["provenance"]["command_line"].get<std::string>().find(kBench), 0u);
    }
    return records;
  }

  static std::vector<json> ofVariant(const std::vector<json>& records, const std::string& variant) {
    std::vector<json> out;
    for (const json& r : records)
      if (r["variant"] == variant) out.push_back(r);
    return out;
  }

  fs::path dir_;
  std::string out_, err_;
};

TEST_F(ScenTest, AStarMatchesTheHandComputedOptimaOfEveryProblem) {
  const std::vector<json> records = runScen(kData + "/wall.scen", "--seeds 2");
  ASSERT_EQ(records.size(), 3 * kOptima.size());  // per problem A* once, then EACI seeds 1 and 2
  const std::vector<json> astar = ofVariant(records, "astar"), eaci = ofVariant(records, "eaci");
  ASSERT_EQ(astar.size(), kOptima.size());
  for (std::size_t k = 0; k < kOptima.size(); ++k) {
    SCOPED_TRACE("problem " + std::to_string(k + 1));
    EXPECT_EQ(astar[k]["problem"]["index"], k);
    EXPECT_EQ(astar[k]["problem"]["problems_in_file"], 6);
    EXPECT_NEAR(astar[k]["problem"]["optimal_length"].get<double>(), kOptima[k], 1e-8);  // the file's value
    EXPECT_NEAR(astar[k]["run"]["length"].get<double>(), kOptima[k], 1e-9);              // A* under our rule
    for (int seed = 1; seed <= 2; ++seed) {
      const json& e = eaci[2 * k + static_cast<std::size_t>(seed) - 1];
      EXPECT_EQ(e["problem"], astar[k]["problem"]);
      EXPECT_EQ(e["seed"], seed);
      EXPECT_TRUE(e["run"]["success"].get<bool>());
      EXPECT_GE(e["run"]["length"].get<double>(), kOptima[k] - 1e-9);  // never shorter than the optimum
    }
    // Only what differs from the defaults: MovingAI's rule is the default one.
    EXPECT_EQ(astar[k]["parameters"], json::object());
  }
  EXPECT_EQ(astar[2]["problem"]["start"], json::array({5, 1}));  // (x 1, y 5) as [row, col]
  EXPECT_EQ(astar[2]["problem"]["goal"], json::array({3, 4}));
  EXPECT_EQ(astar[5]["problem"]["bucket"], 3);
  EXPECT_NE(out_.find("scen.jsonl"), std::string::npos) << out_;
}

// scripts/bench_report.py groups the problems by powers of two of the optimal length: 7, 7, 5
// and 7.83 lie in [4, 8), 9.83 and 11.24 in [8, 16); 12 EACI runs, all solved.
TEST_F(ScenTest, TheReportGroupsProblemsIntoRouteLengthBands) {
  runScen(kData + "/wall.scen", "--seeds 2");
  ASSERT_EQ(run("/usr/bin/python3", quote(EACI_SOURCE_DIR "/scripts/bench_report.py") + " --stdout --records " +
                                        quote((dir_ / "report").string()) + " scen"), 0) << err_;
  EXPECT_NE(out_.find("| 6 of 6 | 0 | 12/12 |"), std::string::npos) << out_;
  EXPECT_NE(out_.find("| 4–8 | 4 | 8/8 |"), std::string::npos) << out_;
  EXPECT_NE(out_.find("| 8–16 | 2 | 4/4 |"), std::string::npos) << out_;
}

TEST_F(ScenTest, EveryKthProblemAndMapDir) {
  // The scenario copied elsewhere: its map is found through --map-dir.
  fs::copy_file(kData + "/wall.scen", dir_ / "copy.scen");
  const std::vector<json> astar = ofVariant(runScen((dir_ / "copy.scen").string(), "--every 2 --map-dir " + quote(kData)), "astar");
  ASSERT_EQ(astar.size(), 3u);  // problems 1, 3, 5
  for (std::size_t n = 0; n < 3; ++n) {
    EXPECT_EQ(astar[n]["problem"]["index"], 2 * n);
    EXPECT_NEAR(astar[n]["run"]["length"].get<double>(), kOptima[2 * n], 1e-9);
  }
}

TEST_F(ScenTest, ParametersFromAFileButCornerCuttingStaysForbidden) {
  std::ofstream(dir_ / "params.yaml") << "ants: 7\nallow_corner_cutting: true\nearly_stop_iterations: 3\n";
  const std::vector<json> records = runScen(kData + "/wall.scen", "--params " + quote((dir_ / "params.yaml").string()));
  ASSERT_EQ(records.size(), 2 * kOptima.size());
  for (std::size_t k = 0; k < records.size(); ++k) {
    EXPECT_EQ(records[k]["parameters"]["ants"], 7);
    EXPECT_EQ(records[k]["parameters"]["early_stop_iterations"], 3);
    EXPECT_FALSE(records[k]["parameters"].contains("allow_corner_cutting"));  // the default: forbidden
    if (records[k]["variant"] == "astar") {  // still the file's optima, not shorter corner-cutting routes
      EXPECT_NEAR(records[k]["run"]["length"].get<double>(), kOptima[k / 2], 1e-9);
    }
  }
  std::ofstream(dir_ / "bad.yaml") << "ants: 0\n";
  EXPECT_NE(run(kBench, "scen " + quote(kData + "/wall.scen") + " --params " + quote((dir_ / "bad.yaml").string())), 0);
  EXPECT_NE(err_.find("ants"), std::string::npos) << err_;
}

TEST_F(ScenTest, AnOptimumWithCornerCuttingIsAMismatch) {
  // Problem 3's length if corners could be cut (3 + √2): A* (no corner cutting) finds 5.
  fs::copy_file(kData + "/wall.map", dir_ / "wall.map");
  std::ofstream(dir_ / "cut.scen") << "version 1\n0\twall.map\t8\t6\t0\t0\t7\t0\t7\n1\twall.map\t8\t6\t1\t5\t4\t3\t4.41421356\n";
  const std::vector<json> astar = ofVariant(runScen((dir_ / "cut.scen").string(), "", 1), "astar");
  ASSERT_EQ(astar.size(), 2u);
  EXPECT_NEAR(astar[1]["run"]["length"].get<double>(), 5.0, 1e-9);
  EXPECT_NE(err_.find("mismatch on problem 2 (line 3)"), std::string::npos) << err_;
  EXPECT_EQ(err_.find("mismatch on problem 1"), std::string::npos) << err_;
}

TEST_F(ScenTest, ProblemsThatDoNotFitTheMapAreRefused) {
  fs::copy_file(kData + "/wall.map", dir_ / "wall.map");
  std::ofstream(dir_ / "size.scen") << "version 1\n0\twall.map\t9\t6\t0\t0\t7\t0\t7\n";
  EXPECT_EQ(run(kBench, "scen " + quote((dir_ / "size.scen").string()) + " --out " + quote(dir_.string())), 2);
  EXPECT_NE(err_.find("size.scen: line 2: map size 9 x 6 but"), std::string::npos) << err_;
  std::ofstream(dir_ / "blocked.scen") << "version 1\n0\twall.map\t8\t6\t0\t2\t7\t0\t7\n";  // (0,2) is '@'
  EXPECT_EQ(run(kBench, "scen " + quote((dir_ / "blocked.scen").string()) + " --out " + quote(dir_.string())), 2);
  EXPECT_NE(err_.find("blocked.scen: line 2: start (x 0, y 2) is blocked"), std::string::npos) << err_;
  std::ofstream(dir_ / "nomap.scen") << "version 1\n0\tmissing.map\t8\t6\t0\t0\t7\t0\t7\n";
  EXPECT_EQ(run(kBench, "scen " + quote((dir_ / "nomap.scen").string()) + " --out " + quote(dir_.string())), 2);
  EXPECT_NE(err_.find("missing.map"), std::string::npos) << err_;
}

TEST_F(ScenTest, EaciPlanReadsTheMovingAiMap) {
  ASSERT_TRUE(fs::exists(kPlan)) << "eaci_plan not built: " << kPlan;
  const std::string map = quote(kData + "/wall.map");
  const fs::path report = dir_ / "plan.json";
  // Problem 4, (x 0, y 0) -> (x 0, y 5): --start and --goal are ROW,COL.
  ASSERT_EQ(run(kPlan, "--map " + map + " --start 0,0 --goal 5,0 --algorithm astar --json " + quote(report.string())), 0) << err_;
  json j = json::parse(readFile(report));
  EXPECT_NEAR(j["length"].get<double>(), 7.0 + 2 * kRoot2, 1e-9);
  // Problem 3 without and with corner cutting.
  ASSERT_EQ(run(kPlan, "--map " + map + " --start 5,1 --goal 3,4 --algorithm astar --json " + quote(report.string())), 0) << err_;
  EXPECT_NEAR(json::parse(readFile(report))["length"].get<double>(), 5.0, 1e-9);
  ASSERT_EQ(run(kPlan, "--map " + map + " --start 5,1 --goal 3,4 --algorithm astar --set allow_corner_cutting=true --json " +
                           quote(report.string())), 0) << err_;
  EXPECT_NEAR(json::parse(readFile(report))["length"].get<double>(), 3.0 + kRoot2, 1e-9);
  // EACI with its defaults: a route no shorter than the optimum, through the gap.
  ASSERT_EQ(run(kPlan, "--map " + map + " --start 0,0 --goal 5,0 --json " + quote(report.string())), 0) << err_;
  j = json::parse(readFile(report));
  EXPECT_GE(j["length"].get<double>(), 7.0 + 2 * kRoot2 - 1e-9);
  bool through_gap = false;
  for (const json& cell : j["path"]) through_gap |= cell == json::array({2, 3});
  EXPECT_TRUE(through_gap);
  // A blocked start cell ('@' at row 2, column 0) is bad input.
  EXPECT_EQ(run(kPlan, "--map " + map + " --start 2,0 --goal 5,0"), 2);
}

}  // namespace
