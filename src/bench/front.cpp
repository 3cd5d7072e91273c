// `front`: the paper's four maps (corner cutting allowed, the paper tables' rule), both objectives
// at once (issue #30): route length against total corner angle.
//   variant "heading"  - the exact search over (cell, heading) states for each turn_cost of the
//                        sweep (turn_cost 0: plain A*, which breaks ties between shortest routes
//                        arbitrarily); extra.turn_cost;
//   variant "pareto"   - the whole exact front, one record per nondominated route: for every
//                        total turning budget of k 45-degree steps the shortest route that turns
//                        by at most k steps, found by a Dijkstra over (cell, heading, steps turned)
//                        states (written here, independent of HeadingSearch); a turn_cost sweep
//                        only finds the front's supported (convex-hull) points, this finds them all;
//   variant "eaci-geodesic", "eaci-paper" - EACI's routes, seeds 1..runs, the paper comparison's
//                        parameters (as `paper`).
// Corner angle: run.total_turn_deg, the grid route's heading change (as the paper tables' angle
// column in `paper`), not the smoothed route's.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>

#include "common/paper_maps.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/grid/moves.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/io/text.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "studies.hpp"

namespace eaci_bench {

namespace {

struct FrontPoint {
  int turn_steps;
  double length;
  eaci::CellPath path;
};

// For k = 0..max_steps: the shortest route from start to goal that turns by at most k 45-degree
// steps in all (the first move turns nothing; the goal may be entered in any direction), kept
// when it is shorter than every route of fewer steps: the Pareto front of (length, turning), both
// minimised, up to max_steps. State (cell, incoming direction or none at the start, steps so far).
std::vector<FrontPoint> exactFront(const eaci::CostGrid& grid, eaci::Cell start, eaci::Cell goal, int max_steps) {
  const std::size_t cells = grid.cellCount();
  const std::size_t headings = eaci::kDirections + 1;  // 8 = no heading yet (the start)
  const std::size_t layers = static_cast<std::size_t>(max_steps) + 1;
  const auto id = [&](std::size_t cell, std::size_t h, std::size_t k) { return (k * headings + h) * cells + cell; };
  const std::size_t n = cells * headings * layers;
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> back(n, -1);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  const std::size_t s = id(grid.index(start), eaci::kDirections, 0);
  dist[s] = 0.0;
  open.push({0.0, s});
  const auto cellOf = [&](std::size_t index) {
    return eaci::Cell{static_cast<int>(index / static_cast<std::size_t>(grid.width())),
                      static_cast<int>(index % static_cast<std::size_t>(grid.width()))};
  };
  while (!open.empty()) {
    const auto [d, state] = open.top();
    open.pop();
    if (d > dist[state]) continue;
    const std::size_t cell = state % cells, h = (state / cells) % headings, k = state / cells / headings;
    const eaci::Cell c = cellOf(cell);
    if (c == goal) continue;  // a route ends at the goal
    const unsigned moves = grid.movesFrom(c);
    for (int dir = 0; dir < eaci::kDirections; ++dir) {
      if (((moves >> dir) & 1u) == 0) continue;
      const std::size_t k2 = k + (h == eaci::kDirections ? 0 : static_cast<std::size_t>(eaci::turnSteps(static_cast<int>(h), dir)));
      if (k2 >= layers) continue;
      const std::size_t next = id(grid.index(eaci::step(c, dir)), static_cast<std::size_t>(dir), k2);
      const double nd = d + eaci::stepLength(dir);
      if (nd < dist[next]) {
        dist[next] = nd;
        back[next] = static_cast<std::int64_t>(state);
        open.push({nd, next});
      }
    }
  }
  std::vector<FrontPoint> front;
  double best_so_far = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < layers; ++k) {
    std::size_t best = n;
    for (std::size_t h = 0; h < headings; ++h) {
      const std::size_t state = id(grid.index(goal), h, k);
      if (best == n || dist[state] < dist[best]) best = state;
    }
    // Strictly shorter than every route that turns less (1e-9: sums of 1 and sqrt 2 in other orders).
    if (!(dist[best] < best_so_far - 1e-9)) continue;
    best_so_far = dist[best];
    FrontPoint p{static_cast<int>(k), dist[best], {}};
    for (std::int64_t x = static_cast<std::int64_t>(best); x >= 0; x = back[static_cast<std::size_t>(x)])
      p.path.push_back(cellOf(static_cast<std::size_t>(x) % cells));
    std::reverse(p.path.begin(), p.path.end());
    front.push_back(std::move(p));
  }
  return front;
}

eaci::Parameters frontParameters(std::uint64_t seed, int threads) {
  eaci::Parameters params;
  eaci::setParameter(params, "allow_corner_cutting", "true");
  params.seed = seed;
  params.threads = threads;
  return params;
}

}  // namespace

void runFront(const FrontOptions& options, RecordWriter& out) {
  Progress progress("front");
  for (const eaci::paper::PaperMap& spec : eaci::paper::loadPaperMaps(options.maps_dir)) {
    if (!spec.has_paper_rows) continue;
    const eaci::OccupancyMap map = eaci::loadMatrixText(options.maps_dir + "/" + spec.file());
    const nlohmann::json problem = {{"start", spec.start}, {"goal", spec.goal}, {"width", map.width}, {"height", map.height}};
    const auto append = [&](const std::string& variant, const eaci::Parameters& params, nlohmann::json run,
                            nlohmann::json extra) {
      Record r;
      r.map = spec.name;
      r.variant = variant;
      r.problem = problem;
      r.params = params;
      r.run = std::move(run);
      r.extra = std::move(extra);
      out.append(r);
    };
    const auto request = [&](eaci::Algorithm algorithm, const eaci::Parameters& params) {
      return TimedPlanRequest{map.view(), spec.start, spec.goal, algorithm, params, 0.0};
    };

    // The exact search for each turn_cost.
    int max_steps = 0;
    for (std::size_t j = 0; j < options.turn_costs.size(); ++j) {
      progress.show(spec.name + " | heading search", static_cast<int>(j) + 1, static_cast<int>(options.turn_costs.size()));
      eaci::Parameters params = frontParameters(1, 1);
      params.turn_cost = options.turn_costs[j];
      nlohmann::json run = timedPlan(request(eaci::Algorithm::kAStar, params), false, true);
      if (run["success"].get<bool>())
        max_steps = std::max(max_steps, static_cast<int>(std::lround(run["total_turn_deg"].get<double>() / 45.0)));
      append("heading", params, std::move(run), {{"turn_cost", options.turn_costs[j]}});
    }

    // The whole front, up to the most turning route above: the shortest route that turns least
    // turns no more than any shortest route (turn_cost 0), so the front ends at or before it.
    {
      progress.show(spec.name + " | exact front", 1, 1);
      const eaci::Parameters params = frontParameters(1, 1);
      const eaci::CostGrid grid = eaci::CostGrid::fromView(map.view(), true);
      for (const FrontPoint& p : exactFront(grid, spec.start, spec.goal, max_steps)) {
        const nlohmann::json run = {{"success", true}, {"length", p.length}, {"total_turn_deg", 45.0 * p.turn_steps},
                                    {"turn_steps", p.turn_steps}, {"path", p.path}};
        append("pareto", params, run, {{"max_turn_steps", max_steps}});
      }
    }

    // EACI's routes.
    for (const std::string strategy : {"geodesic", "paper"}) {
      for (int k = 1; k <= options.runs; ++k) {
        progress.show(spec.name + " | eaci " + strategy, k, options.runs);
        eaci::Parameters params = frontParameters(static_cast<std::uint64_t>(k), options.threads);
        eaci::setParameter(params, "island_strategy", strategy);
        append("eaci-" + strategy, params, timedPlan(request(eaci::Algorithm::kEaci, params), false, true), {});
      }
    }
  }
  progress.finish();
}

}  // namespace eaci_bench
