// Plan time against map size at a fixed short route, through the planning service as the
// move_base plugin drives it (issue #31): the same route of about 3.5 m (70 cells at 0.05 m,
// through a door) on costmaps of rooms from 512 x 512 (0.26 M cells) to 4096 x 4096 (16.8 M),
// with the robot-ready defaults (EACI, one thread, 4 landmarks, 1 s), planned again and again
// on the costmap as it is (Unchanged), and with a few cells changed between plans far from the
// route, as a costmap's obstacle layer changes them (FewChanged); told what changed, as the
// plugin's change tracker tells it, or not (Untold: every row compared with the service's
// copy). Each plan borrows the costmap's cells as the plugin does under the costmap's lock
// (PlanningService::plan on a CostmapView). Prints the per-phase profile of each run's last
// plan (PlanReply::phases) on lines starting with #.
//   build/bin/eaci_service_scale [--benchmark_filter=...] [--benchmark_repetitions=5]
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <thread>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "eaci/grid/inflation.hpp"
#include "eaci/io/map_io.hpp"
#include "planning_service.hpp"

namespace {

// Rooms of 80 x 80 cells (walls of lethal cells, a door of 20 cells in each), inflated as
// costmap_2d inflates them (inscribed 0.15 m, inflation 0.55 m, cost_scaling_factor 10),
// bottom row first as costmap_2d keeps its char map.
eaci_service::CostmapSnapshot roomsCostmap(int size) {
  std::vector<std::uint8_t> walls(static_cast<std::size_t>(size) * size, 0);
  for (int line = 80; line < size; line += 80)
    for (int i = 0; i < size; ++i)
      if (i % 80 < 30 || i % 80 >= 50) {
        walls[static_cast<std::size_t>(line) * size + i] = 1;
        walls[static_cast<std::size_t>(i) * size + line] = 1;
      }
  const eaci::GridView view(walls.data(), size, size, eaci::RowOrder::kTopFirst,
                            eaci::CellInterpretation{});
  eaci::InflationParameters inflation;
  inflation.inscribed_radius = 0.15;
  inflation.inflation_radius = 0.55;
  inflation.cost_scaling_factor = 10.0;
  eaci_service::CostmapSnapshot costmap;
  costmap.cells = eaci::inflatedCosts(view, 0.05, inflation);
  costmap.frame.width = costmap.frame.height = size;
  costmap.frame.resolution = 0.05;
  costmap.frame_id = "map";
  costmap.order = eaci::RowOrder::kTopFirst;
  return costmap;
}

const eaci_service::CostmapSnapshot& costmapOf(int size) {
  static std::map<int, std::unique_ptr<eaci_service::CostmapSnapshot>> made;
  auto& slot = made[size];
  if (!slot) slot = std::make_unique<eaci_service::CostmapSnapshot>(roomsCostmap(size));
  return *slot;
}

void printPhases(int size, const eaci_service::PlanReply& reply) {
  std::printf("# %d x %d: %s", size, size, eaci_service::describePhases(reply.phases).c_str());
  std::printf("\n");
}

// What the plan is told of the costmap's changes: what the plugin's change tracker reports
// (the rectangles costmap_2d rewrote), or nothing (the planner node, a costmap without the
// tracker): then every row is compared with the service's copy.
enum class Told { kChanges, kNothing };

void planShortRoute(benchmark::State& state, bool change_cells, Told told) {
  const int size = static_cast<int>(state.range(0));
  eaci_service::CostmapSnapshot costmap = costmapOf(size);  // this run's own: cells change
  eaci_service::PlanningService service(eaci_service::ServiceSettings{}, eaci_service::Logger{});
  service.configure(eaci_service::rosDefaultParameters(), eaci_service::RosPlannerOptions{}, "");
  eaci_service::PlanRequest request;
  request.start = costmap.frame.cellToWorld({40, 50});   // room (0, 0)
  request.goal = costmap.frame.cellToWorld({40, 110});   // room (0, 1), through the door
  std::mt19937 random(7);
  std::uniform_int_distribution<int> far(size / 2, size - 2);
  eaci_service::PlanReply reply;
  eaci_service::CostmapChanges changes =
      told == Told::kChanges ? eaci_service::CostmapChanges::none() : eaci_service::CostmapChanges::unknown();
  for (auto _ : state) {
    if (change_cells) {  // what an obstacle layer does between two plans, far from the route
      state.PauseTiming();
      changes.rects.clear();
      for (int k = 0; k < 8; ++k) {
        const eaci::Cell cell{far(random), far(random)};
        const std::size_t at = costmap.bufferIndex(cell);
        std::uint8_t& value = costmap.cells[at];
        value = value == eaci_service::kCostmapLethal ? eaci_service::kCostmapFree : eaci_service::kCostmapLethal;
        const int x = static_cast<int>(at % size), y = static_cast<int>(at / size);
        if (told == Told::kChanges) changes.rects.push_back({x, y, x + 1, y + 1});
      }
      state.ResumeTiming();
    }
    reply = service.plan(eaci_service::CostmapView::of(costmap), request, changes);
    if (!reply.ok()) state.SkipWithError(reply.error.c_str());
  }
  state.counters["route_cells"] = static_cast<double>(reply.result.path.size());
  state.counters["Mcells"] = static_cast<double>(size) * size / 1e6;
  printPhases(size, reply);
}

void BM_ServiceShortRouteUnchanged(benchmark::State& state) { planShortRoute(state, false, Told::kChanges); }
void BM_ServiceShortRouteFewChanged(benchmark::State& state) { planShortRoute(state, true, Told::kChanges); }
void BM_ServiceShortRouteUnchangedUntold(benchmark::State& state) { planShortRoute(state, false, Told::kNothing); }
void BM_ServiceShortRouteFewChangedUntold(benchmark::State& state) { planShortRoute(state, true, Told::kNothing); }

// Resident memory of this process, MB (Linux: VmRSS of /proc/self/status; 0 elsewhere).
double residentMegabytes() {
  std::FILE* status = std::fopen("/proc/self/status", "r");
  if (status == nullptr) return 0.0;
  char line[256];
  double kb = 0.0;
  while (std::fgets(line, sizeof(line), status) != nullptr)
    if (std::sscanf(line, "VmRSS: %lf kB", &kb) == 1) break;
  std::fclose(status);
  return kb / 1024.0;
}

// A route across the map (corner room to corner room), repeated on the costmap as it is: the
// plan's work grows with the route here, the part that does not is the map's. Arguments: the
// size, the algorithm (0 EACI, 1 A*) and the landmarks. Counters: the memory the service's kept
// buffers (its copy of the costmap, the grid, the search labels, the colony's region and
// pheromone, the landmarks) add to the process, MB (run one size and algorithm per process for
// a clean figure: --benchmark_filter='RouteAcross/2048/1/0$').
void BM_ServiceRouteAcross(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  const eaci_service::CostmapSnapshot& costmap = costmapOf(size);
  malloc_trim(0);  // what making the costmap freed goes back first
  const double before = residentMegabytes();
  eaci_service::PlanningService service(eaci_service::ServiceSettings{}, eaci_service::Logger{});
  eaci_service::RosPlannerOptions options;
  options.algorithm = state.range(1) == 0 ? eaci::Algorithm::kEaci : eaci::Algorithm::kAStar;
  options.landmarks = static_cast<int>(state.range(2));
  service.configure(eaci_service::rosDefaultParameters(), options, "");
  eaci_service::PlanRequest request;
  request.start = costmap.frame.cellToWorld({40, 40});
  request.goal = costmap.frame.cellToWorld({size - 40, size - 40});
  eaci_service::PlanReply reply;
  for (int warm = 0; warm < 50; ++warm) {  // landmarks made in the background, then used
    reply = service.plan(eaci_service::CostmapView::of(costmap), request, eaci_service::CostmapChanges::none());
    std::this_thread::sleep_for(std::chrono::milliseconds(options.landmarks > 0 ? 20 : 0));
  }
  for (auto _ : state) {
    reply = service.plan(eaci_service::CostmapView::of(costmap), request, eaci_service::CostmapChanges::none());
    if (!reply.ok()) state.SkipWithError(reply.error.c_str());
  }
  state.counters["route_cells"] = static_cast<double>(reply.result.path.size());
  state.counters["kept_MB"] = residentMegabytes() - before;
  printPhases(size, reply);
}
BENCHMARK(BM_ServiceRouteAcross)
    ->ArgsProduct({{400, 1200, 2048}, {0, 1}, {0, 4}})
    ->Unit(benchmark::kMillisecond);

// The nav2 protocol on a map file (issue #31's through-move_base comparison, without ROS): the
// map of $EACI_SCALE_MAP (map_server YAML) inflated as the lab's costmap inflates it (footprint's
// inscribed radius 0.1125 m, inflation 0.55 m, cost_scaling_factor 5), 12 pairs of free cells
// more than 3 m apart drawn with a fixed seed, each planned once per iteration with the plugin's
// defaults (allow_unknown false, as config/move_base_params.yaml). Argument: 0 EACI, 1 A*.
// $EACI_SCALE_LANDMARKS sets the landmarks kept (default 4).
//   EACI_SCALE_MAP=/tmp/mbmaps/rooms400.yaml build/bin/eaci_service_scale --benchmark_filter=MapPairs
void BM_ServiceMapPairs(benchmark::State& state) {
  const char* path = std::getenv("EACI_SCALE_MAP");
  if (path == nullptr) {
    state.SkipWithError("set EACI_SCALE_MAP to a map_server YAML");
    return;
  }
  const eaci::OccupancyMap map = eaci::loadMap(path);
  eaci::InflationParameters inflation;
  inflation.inscribed_radius = 0.1125;
  inflation.inflation_radius = 0.55;
  inflation.cost_scaling_factor = 5.0;
  eaci_service::CostmapSnapshot costmap;
  costmap.cells = eaci::inflatedCosts(map.view(), map.resolution, inflation);
  costmap.frame = map;
  costmap.frame_id = "map";
  costmap.order = eaci::RowOrder::kTopFirst;
  std::vector<eaci::Cell> free_cells;
  for (int r = 0; r < map.height; ++r)
    for (int c = 0; c < map.width; ++c)
      if (costmap.cells[costmap.bufferIndex({r, c})] < eaci_service::kCostmapInscribed) free_cells.push_back({r, c});
  std::mt19937 random(1);
  std::uniform_int_distribution<std::size_t> pick(0, free_cells.size() - 1);
  std::vector<std::pair<eaci::Cell, eaci::Cell>> pairs;
  while (pairs.size() < 12) {
    const eaci::Cell a = free_cells[pick(random)], b = free_cells[pick(random)];
    if (std::hypot(a.row - b.row, a.col - b.col) * map.resolution > 3.0) pairs.push_back({a, b});
  }
  eaci_service::PlanningService service(eaci_service::ServiceSettings{}, eaci_service::Logger{});
  eaci_service::RosPlannerOptions options;
  options.algorithm = state.range(0) == 0 ? eaci::Algorithm::kEaci : eaci::Algorithm::kAStar;
  if (const char* marks = std::getenv("EACI_SCALE_LANDMARKS")) options.landmarks = std::atoi(marks);
  eaci::Parameters parameters = eaci_service::rosDefaultParameters();
  parameters.allow_unknown = false;
  service.configure(parameters, options, "");
  eaci_service::PlanReply reply;
  const auto planAll = [&] {
    for (const auto& [a, b] : pairs) {
      eaci_service::PlanRequest request;
      request.start = costmap.frame.cellToWorld(a);
      request.goal = costmap.frame.cellToWorld(b);
      reply = service.plan(eaci_service::CostmapView::of(costmap), request, eaci_service::CostmapChanges::none());
      if (!reply.ok()) state.SkipWithError(reply.error.c_str());
    }
  };
  for (int warm = 0; warm < 5; ++warm) {  // landmarks made in the background, then used
    planAll();
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  for (auto _ : state) planAll();  // the time is that of 12 plans
  state.counters["plans"] = static_cast<double>(pairs.size());
}
BENCHMARK(BM_ServiceMapPairs)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

#define EACI_SIZES ->Arg(512)->Arg(1024)->Arg(2048)->Arg(4096)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_ServiceShortRouteUnchanged) EACI_SIZES;
BENCHMARK(BM_ServiceShortRouteFewChanged) EACI_SIZES;
BENCHMARK(BM_ServiceShortRouteUnchangedUntold) EACI_SIZES;
BENCHMARK(BM_ServiceShortRouteFewChangedUntold) EACI_SIZES;

}  // namespace

BENCHMARK_MAIN();
