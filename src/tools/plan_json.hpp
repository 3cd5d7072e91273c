// eaci_plan's JSON report: the plan result plus what it was planned on.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "eaci/planner/parameters.hpp"
#include "eaci/grid/cell.hpp"
#include "eaci/grid/end_headings.hpp"
#include "eaci/io/occupancy_map.hpp"
#include "eaci/planner.hpp"

namespace eaci::tools {

// Everything the report needs besides the PlanResult. Fields that are not known yet
// (the run failed before) stay empty and are written as null.
struct PlanContext {
  std::string map_path;
  const OccupancyMap* map = nullptr;    // null when the map could not be loaded
  std::string unknown_policy = "obstacle";  // or "expensive" (allow_unknown: passable at the dearest cost)
  std::optional<Cell> start;
  std::optional<Cell> goal;
  std::optional<Cell> requested_goal;   // the goal asked for, when --tolerance moved it to `goal`
  Parameters parameters;                // as used (or as far as they were read)
  EndHeadings end_headings;             // --start-yaw, --goal-yaw (radians; NaN: none)
  std::optional<double> time_ms;        // wall time of the plan() call; empty if it was not called
  // The cells the planners read when they are not the map's own (--inflate: the map's costmap_2d
  // costs); mean_cell_cost is measured on them (the clearances on the map). Empty: the map.
  std::optional<GridView> planned_on;
  // The run failed before plan() on the arguments themselves (not a status of plan()'s):
  // outcome "bad_input", status null.
  bool bad_input = false;
};

// The JSON's "outcome": a stable snake_case word: "ok" for a route, "bad_input" (above), else
// the status's word (eaci::toString(PlanStatus): no_path, stopped, start_off_map, ...).
std::string outcomeWord(const PlanResult& result, const PlanContext& context);

// The report: success, outcome, error (only when failed), status, algorithm, length, cost, combined_cost, length_m,
// min_clearance_m, smoothed_min_clearance_m, mean_cell_cost, path, path_xy, smoothed_path, smoothed_length,
// iterations_to_converge, iterations_run, stopped_early, interrupted, lost_ants_total,
// ants_per_iteration, lost_ants_per_iteration, best_cost_per_iteration, best_cost_so_far (null where
// infinite; the same again as best_length_per_iteration and best_length_so_far, their names until
// the next release), total_turn_deg, islands (S, islands, E), time_ms, seed, map, unknown, start, goal,
// (requested_goal, only when --tolerance moved the goal), parameters, in this order.
nlohmann::ordered_json planToJson(const PlanResult& result, const PlanContext& context);

// Writes planToJson() to `file`, indented. Throws std::runtime_error with a one-line reason.
void writePlanJson(const std::string& file, const PlanResult& result, const PlanContext& context);

}  // namespace eaci::tools
