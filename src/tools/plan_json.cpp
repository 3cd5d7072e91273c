#include "plan_json.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

#include "common/cell_json.hpp"
#include "common/json_number.hpp"
#include "common/parameters_json.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/metrics/path_metrics.hpp"

namespace eaci::tools {
namespace {

using json = nlohmann::ordered_json;
using report::finiteOrNull;

json optionalCellJson(const std::optional<Cell>& c) { return c ? json(*c) : json(nullptr); }

}  // namespace

std::string outcomeWord(const PlanResult& result, const PlanContext& context) {
  if (context.bad_input) return "bad_input";
  return result.success() ? "ok" : toString(result.status);
}

json planToJson(const PlanResult& r, const PlanContext& context) {
  const OccupancyMap* map = context.map;
  json j;
  j["success"] = r.success();
  j["outcome"] = outcomeWord(r, context);
  if (!r.success()) j["error"] = r.error.empty() ? std::string("failed") : r.error;
  j["status"] = context.bad_input ? json(nullptr) : json(toString(r.status));
  j["algorithm"] = toString(r.algorithm);

  const bool has_length = r.success() && std::isfinite(r.length);
  j["length"] = has_length ? json(r.length) : json(nullptr);
  // The route's cost (the cost model of the parameters); the length on a map without costs.
  j["cost"] = has_length && std::isfinite(r.cost) ? json(r.cost) : json(nullptr);
  // cost + turn_cost x the route's heading change in radians (the objective every planner minimises
  // when turn_cost > 0); equal to cost when turn_cost is 0.
  j["combined_cost"] = has_length && std::isfinite(r.combined_cost) ? json(r.combined_cost) : json(nullptr);
  // The price of a radian the plan used: turn_cost, x the cheapest route's average cell cost with
  // turn_cost_unit route_cell.
  j["turn_price"] = r.turn_price;
  j["length_m"] = has_length && map ? json(r.length * map->resolution) : json(nullptr);
  // Clearance (route cell centre to nearest obstacle cell centre of the map, metres; null without
  // obstacles) and mean cell cost 0..254 of the route, on the grid it was planned on.
  j["min_clearance_m"] = nullptr;
  j["smoothed_min_clearance_m"] = nullptr;
  j["mean_cell_cost"] = nullptr;
  if (has_length && map && !r.path.empty()) {
    const UnknownPolicy unknown = context.unknown_policy == "expensive" ? UnknownPolicy::kExpensive : UnknownPolicy::kObstacle;
    const auto lethal = static_cast<std::uint8_t>(context.parameters.lethal_cost);  // maps of costs (mode: raw)
    // Clearance from the map's own obstacles; costs as planned (--inflate: the inflated costs).
    const CostGrid on_map = CostGrid::fromView(map->view(unknown, lethal), context.parameters.allow_corner_cutting);
    const ObstacleDistances distances = obstacleTransform(on_map);  // one transform for both
    j["min_clearance_m"] = finiteOrNull(minClearance(on_map, r.path, distances) * map->resolution);
    // The same along the smoothed route's lines, where the robot drives.
    if (!r.smoothed_path.empty())
      j["smoothed_min_clearance_m"] =
          finiteOrNull(minPolylineClearance(on_map, r.smoothed_path, distances) * map->resolution);
    const CostGrid planned = context.planned_on
                                 ? CostGrid::fromView(*context.planned_on, context.parameters.allow_corner_cutting)
                                 : on_map;
    j["mean_cell_cost"] = finiteOrNull(meanCellCost(planned, r.path));
  }

  json path = json::array(), path_xy = json::array();
  for (const Cell& c : r.path) {
    path.push_back(c);
    if (map) {
      const Eigen::Vector2d p = map->cellToWorld(c);
      path_xy.push_back(json::array({p.x(), p.y()}));
    }
  }
  j["path"] = std::move(path);
  j["path_xy"] = std::move(path_xy);
  j["smoothed_path"] = r.smoothed_path;  // the corners of the smoothed route (= path without smooth_path)
  j["smoothed_length"] = r.success() ? json(r.smoothed_length) : json(nullptr);

  j["iterations_to_converge"] = r.iterations_to_converge;
  j["iterations_run"] = r.iterations_run;
  j["stopped_early"] = r.stopped_early;
  j["interrupted"] = r.interrupted;
  j["route_from_search"] = r.route_from_search;
  j["lost_ants_total"] = r.lost_ants_total;
  j["ants_per_iteration"] = r.ants_per_iteration;
  j["lost_ants_per_iteration"] = r.lost_ants_per_iteration;
  j["best_cost_per_iteration"] = finiteOrNull(r.iteration_best_cost);
  j["best_cost_so_far"] = finiteOrNull(r.best_cost_so_far);
  // The names before the cost model, the same values, until the next release.
  j["best_length_per_iteration"] = j["best_cost_per_iteration"];
  j["best_length_so_far"] = j["best_cost_so_far"];
  j["total_turn_deg"] = r.success() ? json(r.total_turn_deg) : json(nullptr);

  j["islands"] = r.islands;

  j["time_ms"] = context.time_ms ? json(finiteOrNull(*context.time_ms)) : json(nullptr);
  j["seed"] = context.parameters.seed;

  json m;
  m["path"] = context.map_path;
  if (map) {
    m["width"] = map->width;
    m["height"] = map->height;
    m["resolution"] = map->resolution;
    m["origin"] = json::array({map->origin.x(), map->origin.y(), map->origin_yaw});
  } else {
    m["width"] = m["height"] = m["resolution"] = m["origin"] = nullptr;
  }
  j["map"] = std::move(m);
  j["unknown"] = context.unknown_policy;
  j["start"] = optionalCellJson(context.start);
  j["goal"] = optionalCellJson(context.goal);
  if (map && context.start) {
    const Eigen::Vector2d p = map->cellToWorld(*context.start);
    j["start_xy"] = json::array({p.x(), p.y()});
  } else {
    j["start_xy"] = nullptr;
  }
  if (map && context.goal) {
    const Eigen::Vector2d p = map->cellToWorld(*context.goal);
    j["goal_xy"] = json::array({p.x(), p.y()});
  } else {
    j["goal_xy"] = nullptr;
  }
  if (context.requested_goal) j["requested_goal"] = *context.requested_goal;
  j["parameters"] = report::parametersToJson(context.parameters);
  return j;
}

void writePlanJson(const std::string& file, const PlanResult& result, const PlanContext& context) {
  // One top-level key per line, each value compact (a path of [row, col] pairs stays
  // readable). Invalid UTF-8 (e.g. in a file name) is replaced rather than thrown on.
  const json report = planToJson(result, context);
  std::string text = "{\n";
  std::size_t k = 0;
  for (const auto& item : report.items()) {
    text += "  " + json(item.key()).dump(-1, ' ', false, json::error_handler_t::replace) + ": " +
            item.value().dump(-1, ' ', false, json::error_handler_t::replace) + (++k < report.size() ? ",\n" : "\n");
  }
  text += "}\n";
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write JSON '" + file + "': " + std::strerror(errno));
  out << text;
  out.flush();
  if (!out) throw std::runtime_error("cannot write JSON '" + file + "': write failed");
}

}  // namespace eaci::tools
