// Google Benchmark of the colony's hot loops on the paper's 50 x 50 map (corner cutting
// allowed, the paper's parameters): one ant's walk, one pheromone update, one iteration; and of
// the exact grid search (A*, the search that meets in the middle with and without landmarks,
// making landmarks, the Dijkstra cost field) on a generated 1024 x 1024 building.
//   build/bin/eaci_microbench [--benchmark_filter=...]
// The map is read from $EACI_MAPS_DIR (default maps/paper).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "eaci/io/map_io.hpp"
#include "eaci/planner.hpp"
#include "eaci/search/astar.hpp"
#include "eaci/search/meeting_search.hpp"

namespace {

struct Fixture {
  eaci::CostGrid grid;
  eaci::Parameters params;
  eaci::Cell start{49, 0}, goal{0, 49};

  Fixture() {
    const char* dir = std::getenv("EACI_MAPS_DIR");
    const std::string maps = dir != nullptr ? dir : "maps/paper";
    grid = eaci::CostGrid::fromView(eaci::loadMatrixText(maps + "/paper-50x50.txt").view(), true);
    params.allow_corner_cutting = true;
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void walkSetupFor(eaci::IslandStrategy strategy, benchmark::State& state,
                  const std::function<void(const eaci::WalkSetup&, eaci::PheromoneField&)>& body) {
  const Fixture& f = fixture();
  eaci::Parameters p = f.params;
  p.island_strategy = strategy;
  eaci::IslandPlan islands = eaci::planIslands(f.grid, f.start, f.goal, p);
  eaci::ColonyRegion region = eaci::colonyRegion(f.grid, islands, p);
  eaci::PheromoneField field = eaci::initialIslandPheromone(f.grid, region, islands.islands, p.lambda, p.alpha);
  const eaci::WalkSetup setup(f.grid, std::move(region), field, islands.islands, eaci::HeuristicRule::kTurningAware,
                              p.beta, p.epsilon, std::move(islands.leg_cost));
  for (auto _ : state) body(setup, field);
}

void BM_AntWalk(benchmark::State& state) {
  eaci::AntWalker walker;
  eaci::AntRoute route;
  std::uint64_t ant = 0;
  walkSetupFor(static_cast<eaci::IslandStrategy>(state.range(0)), state,
               [&](const eaci::WalkSetup& setup, eaci::PheromoneField&) {
                 eaci::SplitMix64 rng = eaci::antStream(1, 1, ant++);
                 walker.walk(setup, rng, route);
                 benchmark::DoNotOptimize(route.length);
               });
  state.SetLabel(state.range(0) == 0 ? "geodesic islands" : "paper islands");
}
BENCHMARK(BM_AntWalk)->Arg(0)->Arg(1);

void BM_AdaptiveUpdate(benchmark::State& state) {
  const Fixture& f = fixture();
  std::vector<eaci::AntRoute> routes(static_cast<std::size_t>(f.params.ants));
  eaci::AntWalker walker;
  walkSetupFor(eaci::IslandStrategy::kGeodesic, state, [&](const eaci::WalkSetup& setup, eaci::PheromoneField& field) {
    state.PauseTiming();
    for (std::size_t k = 0; k < routes.size(); ++k) {
      eaci::SplitMix64 rng = eaci::antStream(2, 1, k);
      walker.walk(setup, rng, routes[k]);
    }
    state.ResumeTiming();
    eaci::adaptivePheromoneUpdate(field, routes, 0, 1, f.params.kappa, f.params.q, 69.3);
  });
}
BENCHMARK(BM_AdaptiveUpdate);

void BM_FullPlan(benchmark::State& state) {
  const Fixture& f = fixture();
  eaci::Parameters p = f.params;
  p.island_strategy = static_cast<eaci::IslandStrategy>(state.range(0));
  for (auto _ : state) {
    const auto r = eaci::plan(f.grid, f.start, f.goal, eaci::Algorithm::kEaci, p);
    benchmark::DoNotOptimize(r.length);
  }
  state.SetLabel(state.range(0) == 0 ? "geodesic islands, 100 iterations" : "paper islands, 100 iterations");
}
BENCHMARK(BM_FullPlan)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// A 1024 x 1024 "building": rooms of 64 x 64 cells behind one-cell walls, each wall with a
// door of 6 cells at a place that varies from wall to wall, and an inflation-like cost that
// falls from 200 next to a wall to 0 four cells away. No corner cutting (the ROS rule).
const eaci::CostGrid& buildingGrid() {
  static const eaci::CostGrid grid = [] {
    constexpr int kSize = 1024, kRoom = 64;
    eaci::CostGrid g(kSize, kSize, false);
    const auto door = [](int wall, int room) { return 8 + ((wall * 37 + room * 17) % (kRoom - 20)); };
    for (int r = 0; r < kSize; ++r) {
      for (int c = 0; c < kSize; ++c) {
        const int rr = r % kRoom, cc = c % kRoom;
        const bool wall_row = rr == 0 && r > 0, wall_col = cc == 0 && c > 0;
        const bool in_row_door = wall_row && cc >= door(r / kRoom, c / kRoom) && cc < door(r / kRoom, c / kRoom) + 6;
        const bool in_col_door = wall_col && rr >= door(c / kRoom + 100, r / kRoom) &&
                                 rr < door(c / kRoom + 100, r / kRoom) + 6;
        if ((wall_row && !in_row_door) || (wall_col && !in_col_door && !wall_row)) {
          g.setBlocked(eaci::Cell{r, c}, true);
          continue;
        }
        const int to_wall = std::min({rr, kRoom - rr, cc, kRoom - cc});
        g.setCost(eaci::Cell{r, c}, static_cast<std::uint8_t>(std::max(0, 200 - 50 * to_wall)));
      }
    }
    return g;
  }();
  return grid;
}

// Arg 0: corner to corner (about 1 400 cells of route, the whole map in play); arg 1: a short
// route inside the first room.
void BM_AStarBuilding(benchmark::State& state) {
  const eaci::CostGrid& grid = buildingGrid();
  const eaci::Cell start{3, 3}, goal = state.range(0) == 0 ? eaci::Cell{1020, 1020} : eaci::Cell{5, 9};
  for (auto _ : state) {
    const eaci::CheapestPath p = eaci::cheapestPath(grid, start, goal);
    benchmark::DoNotOptimize(p.cost);
  }
  state.SetLabel(state.range(0) == 0 ? "1024 x 1024, corner to corner" : "1024 x 1024, short route");
}
BENCHMARK(BM_AStarBuilding)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The same routes with one GridSearchWorkspace kept across the plans (as a node that plans
// again and again would keep it).
void BM_AStarBuildingWorkspace(benchmark::State& state) {
  const eaci::CostGrid& grid = buildingGrid();
  const eaci::Cell start{3, 3}, goal = state.range(0) == 0 ? eaci::Cell{1020, 1020} : eaci::Cell{5, 9};
  eaci::GridSearchWorkspace workspace;
  for (auto _ : state) {
    const eaci::CheapestPath p = eaci::cheapestPath(grid, start, goal, workspace);
    benchmark::DoNotOptimize(p.cost);
  }
  state.SetLabel(state.range(0) == 0 ? "1024 x 1024, corner to corner" : "1024 x 1024, short route");
}
BENCHMARK(BM_AStarBuildingWorkspace)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The search that meets in the middle (geodesic islands' route on large maps), corner to
// corner on one thread, with arg landmarks kept (made before the timing starts): its time and
// the cells it takes off its open lists.
void BM_MeetingSearchBuilding(benchmark::State& state) {
  const eaci::CostGrid& grid = buildingGrid();
  const eaci::Cell start{3, 3}, goal{1020, 1020};
  eaci::MeetingSearch search;
  search.useLandmarks(static_cast<int>(state.range(0)));
  if (eaci::LandmarkCache* cache = search.landmarkCache())  // made as a plan asks for them, until they are
    while (!cache->usableFor(grid)) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  for (auto _ : state) {
    const eaci::CellPath route = search.cheapestRoute(grid, start, goal);
    benchmark::DoNotOptimize(route.data());
  }
  state.counters["cells"] = static_cast<double>(search.expandedCells());
  state.SetLabel("1024 x 1024, corner to corner, " + std::to_string(state.range(0)) + " landmarks");
}
BENCHMARK(BM_MeetingSearchBuilding)->Arg(0)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

// Making arg landmarks on the building (what the ROS plugin does once per costmap, in the background).
void BM_LandmarksBuilding(benchmark::State& state) {
  const eaci::CostGrid& grid = buildingGrid();
  for (auto _ : state) {
    const auto landmarks = eaci::Landmarks::compute(grid, static_cast<int>(state.range(0)));
    benchmark::DoNotOptimize(landmarks.get());
  }
}
BENCHMARK(BM_LandmarksBuilding)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

// A backward Dijkstra search (a leg cost field's) over the whole building (every free cell settled).
void BM_CostFieldBuilding(benchmark::State& state) {
  const eaci::CostGrid& grid = buildingGrid();
  eaci::GridSearchRequest request;
  request.source = eaci::Cell{1020, 1020};
  request.reverse_costs = true;
  for (auto _ : state) {
    const eaci::GridSearchResult field = eaci::searchGrid(grid, request);
    benchmark::DoNotOptimize(field.at(eaci::Cell{0, 0}));
  }
}
BENCHMARK(BM_CostFieldBuilding)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
