// Google Benchmark of the colony's hot loops on the paper's 50 x 50 map (corner cutting
// allowed, the paper's parameters): one ant's walk, one pheromone update, one iteration.
//   build/bin/eaci_microbench [--benchmark_filter=...]
// The map is read from $EACI_MAPS_DIR (default maps/paper).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>

#include "eaci/io/map_io.hpp"
#include "eaci/planner.hpp"

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
                              p.beta, p.epsilon, std::move(islands.leg_distance));
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

}  // namespace

BENCHMARK_MAIN();
