// Shared helpers of the test suite: where the paper maps are, and a path checker
// written independently of the planner's own code.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <set>
#include <string>
#include <utility>

#include "eaci/grid/cost_grid.hpp"
#include "eaci/io/map_io.hpp"
#include "../src/common/paper_maps.hpp"

namespace eaci::test {

// The paper's benchmark maps: maps/paper of the source tree, or $EACI_MAPS_DIR.
inline std::string mapsDir() {
  const char* env = std::getenv("EACI_MAPS_DIR");
  return env != nullptr && *env != '\0' ? std::string(env) : std::string(EACI_SOURCE_DIR "/maps/paper");
}

// A paper benchmark map (maps/paper/<name>) as a CostGrid; a missing file fails the test
// with the loader's message (it names the path).
inline CostGrid paperMap(const std::string& name, bool allow_corner_cutting) {
  const OccupancyMap map = loadMatrixText(mapsDir() + "/" + name);
  return CostGrid::fromView(map.view(), allow_corner_cutting);
}

// The maps of the paper's Tables 1-3 with their start and goal cells and optima, from
// maps/paper/paper_maps.json (the one source of these numbers; a missing file fails).
struct PaperCase {
  std::string file;
  Cell start;
  Cell goal;
  double optimum_cutting;    // corner cutting allowed
  double optimum_no_cutting; // forbidden; < 0: no path
};

inline const std::vector<PaperCase>& paperCases() {
  static const std::vector<PaperCase> cases = [] {
    std::vector<PaperCase> out;
    for (const paper::PaperMap& m : paper::loadPaperMaps(mapsDir()))
      if (!m.table.empty())
        out.push_back({m.file(), m.start, m.goal, m.optimum_corner_cutting,
                       std::isfinite(m.optimum_no_corner_cutting) ? m.optimum_no_corner_cutting : -1.0});
    return out;
  }();
  return cases;
}

// Checks the route properties every planner must give, from first principles:
// starts at S, ends at E, consecutive cells 8-neighbours, every cell free, no cell
// twice, no corner cut unless allowed. Returns "" or what is wrong.
inline std::string routeDefect(const CostGrid& grid, const CellPath& path, Cell start, Cell goal) {
  if (path.empty()) return "empty path";
  if (!(path.front() == start)) return "does not start at S";
  if (!(path.back() == goal)) return "does not end at E";
  std::set<std::pair<int, int>> seen;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const Cell c = path[k];
    if (c.row < 0 || c.col < 0 || c.row >= grid.height() || c.col >= grid.width()) return "leaves the map";
    if (grid.isBlocked(c)) return "enters an obstacle at step " + std::to_string(k);
    if (!seen.insert({c.row, c.col}).second) return "revisits a cell at step " + std::to_string(k);
    if (k == 0) continue;
    const int dr = c.row - path[k - 1].row, dc = c.col - path[k - 1].col;
    if (std::abs(dr) > 1 || std::abs(dc) > 1 || (dr == 0 && dc == 0)) return "jumps at step " + std::to_string(k);
    if (dr != 0 && dc != 0 && !grid.allowCornerCutting()) {
      if (grid.isBlocked(Cell{path[k - 1].row + dr, path[k - 1].col}) ||
          grid.isBlocked(Cell{path[k - 1].row, path[k - 1].col + dc}))
        return "cuts a corner at step " + std::to_string(k);
    }
  }
  return "";
}

// Length from first principles: count straight and diagonal steps.
inline double countedLength(const CellPath& path) {
  int straight = 0, diagonal = 0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const bool diag = path[k].row != path[k - 1].row && path[k].col != path[k - 1].col;
    (diag ? diagonal : straight)++;
  }
  return straight + diagonal * std::sqrt(2.0);
}

// A fresh directory per test under the build directory (`<EACI_BINARY_DIR>/<prefix>/<test>_<pid>`),
// removed afterwards. Only where the build defines EACI_BINARY_DIR (the eaci_tests binary).
#ifdef EACI_BINARY_DIR
class ScratchDirTest : public ::testing::Test {
 protected:
  explicit ScratchDirTest(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::path(EACI_BINARY_DIR) / prefix_ /
           (std::string(info->name()) + "_" + std::to_string(static_cast<long>(::getpid())));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string prefix_;
  std::filesystem::path dir_;
};
#endif

// Success when `message` is one line containing every one of `parts`.
inline ::testing::AssertionResult isOneLineWith(const std::string& message, std::initializer_list<std::string> parts) {
  if (message.find('\n') != std::string::npos) return ::testing::AssertionFailure() << "not one line: " << message;
  for (const std::string& part : parts)
    if (message.find(part) == std::string::npos)
      return ::testing::AssertionFailure() << "'" << part << "' missing from: " << message;
  return ::testing::AssertionSuccess();
}

}  // namespace eaci::test
