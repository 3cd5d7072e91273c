// `front`: the paper's four maps (corner cutting allowed, the paper tables' rule), both objectives
// at once (issue #30): route length against total corner angle.
//   variant "heading"  - the exact search over (cell, heading) states for each turn_cost of the
//                        sweep (turn_cost 0: plain A*, which breaks ties between shortest routes
//                        arbitrarily); extra.turn_cost;
//   variant "pareto"   - the whole exact front, one record per nondominated route: for every
//                        total turning budget of k 45-degree steps the shortest route that turns
//                        by at most k steps, found by a Dijkstra over (cell, heading, steps turned)
//                        states (exactFront, exact_front.hpp, independent of HeadingSearch); a
//                        turn_cost sweep only finds the front's supported (convex-hull) points,
//                        this finds them all;
//   variant "eaci-geodesic", "eaci-paper" - EACI's routes, seeds 1..runs, the paper comparison's
//                        parameters (as `paper`), for each of eaci_turn_costs; extra.turn_cost.
// Corner angle: run.total_turn_deg, the grid route's heading change (as the paper tables' angle
// column in `paper`), not the smoothed route's.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common/paper_maps.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/io/text.hpp"
#include "exact_front.hpp"
#include "progress.hpp"
#include "record.hpp"
#include "studies.hpp"

namespace eaci_bench {

namespace {

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

    // EACI's routes, scoring turns at each of a few turn_cost values (0: as the paper).
    for (const double turn_cost : options.eaci_turn_costs) {
      for (const std::string strategy : {"geodesic", "paper"}) {
        for (int k = 1; k <= options.runs; ++k) {
          progress.show(spec.name + " | eaci " + strategy + " turn_cost " + eaci::formatNumber(turn_cost), k,
                        options.runs);
          eaci::Parameters params = frontParameters(static_cast<std::uint64_t>(k), options.threads);
          eaci::setParameter(params, "island_strategy", strategy);
          params.turn_cost = turn_cost;
          append("eaci-" + strategy, params, timedPlan(request(eaci::Algorithm::kEaci, params), false, true),
                 {{"turn_cost", turn_cost}});
        }
      }
    }
  }
  progress.finish();
}

}  // namespace eaci_bench
