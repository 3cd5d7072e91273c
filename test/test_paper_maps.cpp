// EACI and classic ACO on the paper's benchmark maps (corner cutting allowed, as the
// paper's numbers need), seeds 1-20, against expectations computed independently by A*.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "eaci/planner.hpp"
#include "test_support.hpp"

using eaci::Algorithm;
using eaci::CostGrid;
using eaci::Cell;

namespace {

// Shortest route that visits the islands in order: A* leg by leg.
double shortestRouteThrough(const CostGrid& grid, const std::vector<Cell>& islands) {
  double total = 0.0;
  for (std::size_t k = 0; k + 1 < islands.size(); ++k) {
    const auto leg = eaci::cheapestPath(grid, islands[k], islands[k + 1]);
    if (!leg.found) return std::numeric_limits<double>::infinity();
    total += leg.length;
  }
  return total;
}

struct MapRuns {
  int runs = 0;
  int through_islands_optimal = 0;
};

MapRuns runEaciTwentySeeds(const eaci::test::PaperCase& pc,
                           eaci::IslandStrategy strategy = eaci::IslandStrategy::kPaper) {
  const CostGrid grid = eaci::test::paperMap(pc.file, true);
  MapRuns stats;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    eaci::Parameters p;
    p.allow_corner_cutting = true;
    p.island_strategy = strategy;
    p.seed = seed;
    const auto r = eaci::plan(grid, pc.start, pc.goal, Algorithm::kEaci, p);
    EXPECT_TRUE(r.success()) << pc.file << " seed " << seed << ": " << r.error;
    if (!r.success()) continue;
    EXPECT_EQ(eaci::test::routeDefect(grid, r.path, pc.start, pc.goal), "") << pc.file << " seed " << seed;
    EXPECT_NEAR(r.length, eaci::test::countedLength(r.path), 1e-9);
    EXPECT_GE(r.length, pc.optimum_cutting - 1e-4);
    // The route passes every island, in order.
    std::size_t next = 0;
    for (const Cell& c : r.path)
      if (next < r.islands.size() && c == r.islands[next]) ++next;
    EXPECT_EQ(next, r.islands.size()) << pc.file << " seed " << seed;
    const double through = shortestRouteThrough(grid, r.islands);
    EXPECT_LE(r.length, 1.10 * through + 1e-9) << pc.file << " seed " << seed;
    ++stats.runs;
    if (std::abs(r.length - through) < 1e-6) ++stats.through_islands_optimal;
    // The per-iteration records cover every iteration and add up.
    EXPECT_EQ(r.iterations_run, p.max_iterations);
    EXPECT_EQ(r.lost_ants_per_iteration.size(), static_cast<std::size_t>(r.iterations_run));
    long long lost = 0;
    for (int l : r.lost_ants_per_iteration) lost += l;
    EXPECT_EQ(lost, r.lost_ants_total);
    EXPECT_NEAR(r.best_cost_so_far.back(), r.length, 1e-9);
    EXPECT_NEAR(r.best_cost_so_far[static_cast<std::size_t>(r.iterations_to_converge - 1)], r.length, 1e-9);
  }
  return stats;
}

}  // namespace

// The faithful reading: islands exactly as the paper defines them (island_strategy = paper).
TEST(PaperMaps, EaciStaysWithinTenPercentOfTheBestRouteThroughItsIslands) {
  for (const auto& pc : eaci::test::paperCases()) {
    const MapRuns stats = runEaciTwentySeeds(pc);
    EXPECT_EQ(stats.runs, 20) << pc.file;
  }
}

TEST(PaperMaps, EaciFindsTheRouteThroughItsIslandsWhereLegsDoNotOverlap) {
  // 30x30: the islands lie on an optimal route. The paper's EACI length there, a mean over 20
  // runs, is the optimum 44.53; no run can be shorter, so every one of its runs found it:
  // so must every one here.
  const auto& cases = eaci::test::paperCases();
  const MapRuns thirty = runEaciTwentySeeds(cases[1]);
  EXPECT_EQ(thirty.through_islands_optimal, 20);
  // 40x40: the best route through the islands is the paper's own 59.2548 (optimum 58.0833).
  // The paper's mean 59.25 says every run of the authors found it; the faithful reading here
  // finds it in 57 of seeds 1-100 (11 of seeds 1-20), a known gap (docs/algorithm.md). So this
  // bound is not the paper's: it keeps that reading from getting worse (a broken walk or update
  // gets (near) none).
  const MapRuns forty = runEaciTwentySeeds(cases[2]);
  EXPECT_GE(forty.through_islands_optimal, 8);
}

TEST(PaperMaps, FortyMapEaciRouteIsThePapersFigure) {
  const CostGrid grid = eaci::test::paperMap("paper-40x40.txt", true);
  eaci::Parameters p;
  p.allow_corner_cutting = true;
  p.island_strategy = eaci::IslandStrategy::kPaper;
  double best = std::numeric_limits<double>::infinity();
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    p.seed = seed;
    best = std::min(best, eaci::plan(grid, Cell{0, 0}, Cell{39, 39}, Algorithm::kEaci, p).length);
  }
  EXPECT_NEAR(best, 59.2548, 1e-4);
}

// Beyond the paper (island_strategy = geodesic, the default): islands on a shortest route
// cost nothing, and every run finds the global optimum, 58.0833 and 72.8112 included.
TEST(PaperMaps, GeodesicIslandsReachTheGlobalOptimumEveryRun) {
  for (const auto& pc : eaci::test::paperCases()) {
    const MapRuns stats = runEaciTwentySeeds(pc, eaci::IslandStrategy::kGeodesic);
    EXPECT_EQ(stats.through_islands_optimal, 20) << pc.file;
    const CostGrid grid = eaci::test::paperMap(pc.file, true);
    eaci::Parameters p;
    p.allow_corner_cutting = true;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      p.seed = seed;
      EXPECT_NEAR(eaci::plan(grid, pc.start, pc.goal, Algorithm::kEaci, p).length, pc.optimum_cutting, 1e-4)
          << pc.file << " seed " << seed;
    }
  }
}

TEST(PaperMaps, ClassicAcoFindsValidRoutes) {
  for (const auto& pc : eaci::test::paperCases()) {
    const CostGrid grid = eaci::test::paperMap(pc.file, true);
    eaci::Parameters p;
    p.allow_corner_cutting = true;
    p.seed = 3;
    const auto r = eaci::plan(grid, pc.start, pc.goal, Algorithm::kAco, p);
    ASSERT_TRUE(r.success()) << pc.file << ": " << r.error;
    EXPECT_EQ(eaci::test::routeDefect(grid, r.path, pc.start, pc.goal), "") << pc.file;
    EXPECT_GE(r.length, pc.optimum_cutting - 1e-4);
    EXPECT_LE(r.length, 1.3 * pc.optimum_cutting);
    EXPECT_EQ(r.islands.size(), 2u);
  }
}

// ---------------------------------------------------------------- the paper's Tables 1-3
// Bounds from the paper's own rows (docs: /work/shared/eaci-spec.md section 5), each mean over
// seeds 1-20 as the paper's rows are means over 20 runs:
//   EACI:        1 / 1.4 / 6.2 / 7.1 iterations to converge, 9.85 / 27.5 / 47.6 / 99.2 lost ants;
//   classic ACO: 40.5 / 77.1 / 100 / 100 iterations, 1246 / 3112 / 3994 / 3989 lost ants,
//                best lengths 30.97 / 45.36 / 63.94 / 81.60.
// ACO's own iteration and lost-ant rows give no bound that can fail (100 = Nc_max: it never
// settled; lost ants cannot exceed m x Nc_max = 5,000), so ACO is held to its best length and
// EACI to its row and to the comparison on the same seeds. EACI's best lengths are no bound
// here: with the paper's islands the 20x20 route is 41.21 (docs/algorithm.md explains why); the
// geodesic islands reach the optimum (GeodesicIslandsReachTheGlobalOptimumEveryRun).
namespace {

struct PaperRow {
  double iterations;  // mean iterations to converge
  double lost_ants;   // mean lost ants per run
  double best_length; // shortest route of the 20 runs
};

constexpr PaperRow kPaperEaci[] = {{1, 9.85, 30.97}, {1.4, 27.5, 44.53}, {6.2, 47.6, 59.25}, {7.1, 99.2, 72.81}};
constexpr PaperRow kPaperAco[] = {{40.5, 1246, 30.97}, {77.1, 3112, 45.36}, {100, 3994, 63.94}, {100, 3989, 81.60}};

// The means over seeds 1-20 on a paper map (corner cutting allowed, the paper's parameters).
PaperRow measuredRow(const eaci::test::PaperCase& pc, Algorithm algorithm) {
  const CostGrid grid = eaci::test::paperMap(pc.file, true);
  PaperRow row{0.0, 0.0, std::numeric_limits<double>::infinity()};
  constexpr int kRuns = 20;
  for (std::uint64_t seed = 1; seed <= kRuns; ++seed) {
    eaci::Parameters p;
    p.allow_corner_cutting = true;
    p.island_strategy = eaci::IslandStrategy::kPaper;  // the paper's islands (ACO has none)
    p.seed = seed;
    const auto r = eaci::plan(grid, pc.start, pc.goal, algorithm, p);
    EXPECT_TRUE(r.success()) << pc.file << " seed " << seed << ": " << r.error;
    if (!r.success()) return PaperRow{1e9, 1e9, 1e9};
    EXPECT_GE(r.length, pc.optimum_cutting - 1e-4) << pc.file << " seed " << seed;  // the optimum is a hard floor
    row.iterations += r.iterations_to_converge;
    row.lost_ants += static_cast<double>(r.lost_ants_total);
    row.best_length = std::min(row.best_length, r.length);
  }
  row.iterations /= kRuns;
  row.lost_ants /= kRuns;
  return row;
}

}  // namespace

// EACI reproduces its row of the paper: a reimplementation from the text may differ from the
// authors' code by seed noise and by the readings docs/algorithm.md lists, so a mean up to
// twice the paper's passes; more is not the paper's result. The bounds (2 / 2.8 / 12.4 / 14.2
// iterations of Nc_max = 100, 19.7 / 55 / 95.2 / 198.4 lost ants of 5,000) lie far inside what
// a run can produce. Checked once to fail: with beta = 0 (no heuristic) the means are
// 15.5 / 33.6 / 21.6 iterations and 344 / 1228 / 748 lost ants, and on the 50x50 15 of the 20
// runs find no route (every map fails);
// with a colony of 5 ants the 20x20 takes 3.05 iterations (fails).
TEST(PaperMaps, EaciRowIsWithinTwiceThePapersIterationsAndLostAnts) {
  const auto& cases = eaci::test::paperCases();
  for (std::size_t m = 0; m < cases.size(); ++m) {
    const PaperRow row = measuredRow(cases[m], Algorithm::kEaci);
    EXPECT_LE(row.iterations, 2 * kPaperEaci[m].iterations) << cases[m].file;
    EXPECT_LE(row.lost_ants, 2 * kPaperEaci[m].lost_ants) << cases[m].file;
  }
}

// The paper's central claim (Tables 1-3): on every map EACI converges in fewer iterations and
// loses fewer ants than classic ACO. Compared on the same seeds; only the direction is the
// paper's (its ratios, 14-55x in iterations and 40-126x in lost ants, depend on ACO's tau0 and
// rho, which the paper does not give). Checked once to fail: EACI with beta = 0 loses 4631 ants
// a run on the 50x50 (in the 5 runs that arrive) against ACO's 3544. Both hold as well with the
// spec prototype's ACO tau0 = 1, rho = 0.3 (ACO 10-39 iterations, 56-371 lost ants), as does the
// best-length bound below: none rests on the defaults tau0 = 800, rho = 0.1.
TEST(PaperMaps, EaciConvergesSoonerAndLosesFewerAntsThanClassicAcoOnEveryMap) {
  for (const auto& pc : eaci::test::paperCases()) {
    const PaperRow eaci_row = measuredRow(pc, Algorithm::kEaci);
    const PaperRow aco_row = measuredRow(pc, Algorithm::kAco);
    EXPECT_LT(eaci_row.iterations, aco_row.iterations) << pc.file;
    EXPECT_LT(eaci_row.lost_ants, aco_row.lost_ants) << pc.file;
  }
}

// Classic ACO's best route over the 20 runs is no longer than the paper's ACO best length
// (its table's lengths are rounded to 0.01: + 0.005), and never shorter than the A* optimum.
// Checked once to fail: with beta = 0 the best routes are 31.80 / 52.53 / 82.57 (and 12 of 20
// runs on the 50x50 find none), with 5 ants 31.56 / 46.53 / 66.43 / 101.05: above the paper's
// 30.97 / 45.36 / 63.94 / 81.60 on three maps or four.
TEST(PaperMaps, ClassicAcoBestRouteIsNoLongerThanThePapersAcoBest) {
  const auto& cases = eaci::test::paperCases();
  for (std::size_t m = 0; m < cases.size(); ++m) {
    const PaperRow row = measuredRow(cases[m], Algorithm::kAco);
    EXPECT_LE(row.best_length, kPaperAco[m].best_length + 0.005) << cases[m].file;
  }
}
