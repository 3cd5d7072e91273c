// Shared helpers of the test suite: where the paper maps are, and a path checker
// written independently of the planner's own code.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

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

// The suite's one reference Dijkstra, written from the move rule of the spec
// (/work/shared/eaci-spec.md section 2, the cost rule of global_planner) and not with the
// planner's CostGrid::canMove / moveCost:
//  - 8-connected: from (r, c) to (r + dr, c + dc), dr, dc in {-1, 0, 1}, not both 0;
//  - the cell moved into must be open (free, on the map, inside any window the caller sets);
//  - a diagonal move passes the corner of (r + dr, c) and (r, c + dc): without corner cutting
//    both must be open too; with corner cutting (the paper's benchmarks) they need not be;
//  - a straight move is 1 long, a diagonal sqrt(2); the move costs its length x
//    (neutral_cost + cost_factor x k) / neutral_cost, k the cost 0..254 of the cell it enters
//    (k = 0 everywhere: the route's cost is its length).
struct ReferenceGrid {
  int width = 0;
  int height = 0;
  std::function<bool(int row, int col)> open;                              // asked only on the map
  std::function<int(int row, int col)> cost = [](int, int) { return 0; };  // of an open cell
  bool corner_cutting = false;
  double neutral_cost = 50.0;
  double cost_factor = 3.0;
};

// The cheapest route's cost from `source` to every cell (reverse: from every cell to
// `source`, each move costed by the cell it enters on that way), by row x width + col;
// infinity where no route is. A closed source reaches nothing.
inline std::vector<double> referenceCosts(const ReferenceGrid& g, Cell source, bool reverse = false) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> best(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height), inf);
  const auto open = [&](int r, int c) { return r >= 0 && c >= 0 && r < g.height && c < g.width && g.open(r, c); };
  if (!open(source.row, source.col)) return best;
  const auto at = [&](int r, int c) { return static_cast<std::size_t>(r) * static_cast<std::size_t>(g.width) + c; };
  std::set<std::pair<double, std::size_t>> queue;  // (cost, cell): the cheapest first
  best[at(source.row, source.col)] = 0.0;
  queue.insert({0.0, at(source.row, source.col)});
  while (!queue.empty()) {
    const auto [cost, here] = *queue.begin();
    queue.erase(queue.begin());
    const int r = static_cast<int>(here / static_cast<std::size_t>(g.width));
    const int c = static_cast<int>(here % static_cast<std::size_t>(g.width));
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        if ((dr == 0 && dc == 0) || !open(r + dr, c + dc)) continue;
        const bool diagonal = dr != 0 && dc != 0;
        if (diagonal && !g.corner_cutting && !(open(r + dr, c) && open(r, c + dc))) continue;
        // Forward the move enters (r + dr, c + dc); reversed, the route's move goes from
        // there into (r, c).
        const int entered = reverse ? g.cost(r, c) : g.cost(r + dr, c + dc);
        const double length = diagonal ? std::sqrt(2.0) : 1.0;
        const double next_cost = cost + length * (g.neutral_cost + g.cost_factor * entered) / g.neutral_cost;
        const std::size_t next = at(r + dr, c + dc);
        if (next_cost < best[next]) {
          queue.erase({best[next], next});
          best[next] = next_cost;
          queue.insert({next_cost, next});
        }
      }
    }
  }
  return best;
}

// A CostGrid read as a ReferenceGrid: its free cells (inside `window_open` when given), cell
// costs, corner rule and cost rule; the move rule stays the one written above.
inline ReferenceGrid referenceGridOf(const CostGrid& grid, std::function<bool(int, int)> window_open = {}) {
  ReferenceGrid g;
  g.width = grid.width();
  g.height = grid.height();
  g.open = [&grid, window_open](int r, int c) {
    return !grid.isBlocked(Cell{r, c}) && (!window_open || window_open(r, c));
  };
  g.cost = [&grid](int r, int c) { return static_cast<int>(grid.cost(Cell{r, c})); };
  g.corner_cutting = grid.allowCornerCutting();
  g.neutral_cost = grid.costRule().neutral_cost;
  g.cost_factor = grid.costRule().cost_factor;
  return g;
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
