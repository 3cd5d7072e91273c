// Soak: 10,000 plans with random start and goal on the lab map and on generated maps through
// the core API. Every route must be valid, every failure must be a true "no path", and the
// process must not grow. Run by CTest in the plain build (label "soak"); prints its figures.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

#include "eaci/random.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/planner.hpp"
#include "test_support.hpp"

namespace {

// Resident set size of this process, MiB (Linux).
double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// A random map: blocks of 1-5 cells covering about a quarter of it.
eaci::CostGrid generatedMap(int rows, int cols, eaci::SplitMix64& rng) {
  eaci::CostGrid grid(cols, rows, false);
  const int blocks = rows * cols / 20;
  for (int k = 0; k < blocks; ++k) {
    const int r = static_cast<int>(rng.next() % rows), c = static_cast<int>(rng.next() % cols);
    const int h = 1 + static_cast<int>(rng.next() % 5), w = 1 + static_cast<int>(rng.next() % 5);
    for (int i = r; i < std::min(rows, r + h); ++i)
      for (int j = c; j < std::min(cols, c + w); ++j) grid.setBlocked(eaci::Cell{i, j}, true);
  }
  return grid;
}

eaci::Cell randomFreeCell(const eaci::CostGrid& grid, eaci::SplitMix64& rng) {
  for (;;) {
    const eaci::Cell c{static_cast<int>(rng.next() % static_cast<unsigned>(grid.height())),
                       static_cast<int>(rng.next() % static_cast<unsigned>(grid.width()))};
    if (grid.isFree(c)) return c;
  }
}

struct Tally {
  int plans = 0, routes = 0, no_path = 0, ants_all_lost = 0;
};

void planRandomly(const eaci::CostGrid& grid, int plans, eaci::SplitMix64& rng, Tally& tally) {
  eaci::Parameters params;
  params.early_stop_iterations = 5;  // soak is about validity and memory, not route quality
  for (int k = 0; k < plans; ++k) {
    const eaci::Cell start = randomFreeCell(grid, rng), goal = randomFreeCell(grid, rng);
    const int pick = static_cast<int>(rng.next() % 10);
    const eaci::Algorithm algorithm =
        pick == 0 ? eaci::Algorithm::kAStar : pick == 1 ? eaci::Algorithm::kAco : eaci::Algorithm::kEaci;
    params.island_strategy = pick == 2 ? eaci::IslandStrategy::kPaper : eaci::IslandStrategy::kGeodesic;
    params.seed = rng.next();
    const auto r = eaci::plan(grid, start, goal, algorithm, params);
    const bool reachable = eaci::cheapestPath(grid, start, goal).found;
    ++tally.plans;
    if (r.success()) {
      ++tally.routes;
      ASSERT_TRUE(reachable);
      ASSERT_EQ(eaci::test::routeDefect(grid, r.path, start, goal), "")
          << eaci::toString(algorithm) << " from (" << start.row << "," << start.col << ") to (" << goal.row << ","
          << goal.col << ")";
    } else {
      ++tally.no_path;
      ASSERT_EQ(r.status, eaci::PlanStatus::kNoPath) << r.error;
      // Classic ACO and EACI with the paper's islands may lose every ant where a path exists
      // (documented); A* and EACI with the default geodesic islands must not.
      const bool may_lose_all = algorithm == eaci::Algorithm::kAco || params.island_strategy == eaci::IslandStrategy::kPaper;
      if (may_lose_all && reachable) {
        ++tally.ants_all_lost;
        continue;
      }
      if (!may_lose_all)
        ASSERT_FALSE(reachable) << r.error << " (" << eaci::toString(algorithm) << ", " << eaci::toString(params.island_strategy) << " islands, " << grid.width() << "x" << grid.height() << ", from (" << start.row << "," << start.col << ") to (" << goal.row << "," << goal.col << "))";
    }
  }
}

}  // namespace

TEST(Soak, TenThousandRandomPlansStayValidAndDoNotGrow) {
  const eaci::OccupancyMap lab = eaci::loadMap(std::string(EACI_SOURCE_DIR) + "/maps/lab.yaml");
  const eaci::CostGrid lab_grid = eaci::CostGrid::fromView(lab.view(), false);
  eaci::SplitMix64 rng(2026);
  Tally tally;
  const auto begin = std::chrono::steady_clock::now();
  planRandomly(lab_grid, 1000, rng, tally);  // warm-up: allocator pools, first-touch pages
  const double warm = residentMiB();
  planRandomly(lab_grid, 5000, rng, tally);
  for (int m = 0; m < 40; ++m) {
    const eaci::CostGrid grid = generatedMap(30 + 2 * m, 40 + 2 * m, rng);
    planRandomly(grid, 100, rng, tally);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  const double end = residentMiB();
  std::printf("[ soak ] %d plans (%d routes, %d no path, of which %d classic ACO / paper-island EACI runs lost every "
              "ant where a route exists) in %.1f s; resident %.1f MiB after 1,000 plans, %.1f MiB after %d\n",
              tally.plans, tally.routes, tally.no_path, tally.ants_all_lost, seconds, warm, end, tally.plans);
  EXPECT_EQ(tally.plans, 10000);
  EXPECT_LT(end - warm, 8.0) << "the process grew while planning";
}
