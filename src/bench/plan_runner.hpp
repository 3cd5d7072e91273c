// Runs eaci::plan() once, timed, and turns its result into a RunRecord; also records
// pheromone snapshots (the strongest edge leaving each cell) at chosen iterations.
#pragma once

#include <vector>

#include "eaci/planner/parameters.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/planner.hpp"
#include "run_record.hpp"

namespace eaci_bench {

struct PlanRequest {
  eaci::GridView view;
  eaci::Cell start;
  eaci::Cell goal;
  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;
  eaci::Parameters params;
  double budget_ms = 0.0;  // > 0: stop between iterations once this much wall time has passed
  // Buffers and threads kept between plans (as the ROS node and plugin keep theirs); null: the plan's own.
  eaci::PlannerWorkspace* workspace = nullptr;
};

// Wall time is measured around plan() alone; an observer notes the end of each iteration
// (it only reads the clock) to give the time until the final route was found.
RunRecord timedPlan(const PlanRequest& request);

struct PheromoneSnapshot {
  int iteration = 0;               // 0 = the initial field
  std::vector<double> strongest;   // per cell, row-major: PheromoneField::strongestFrom
};

// One untimed run that copies the field at the listed iterations.
std::vector<PheromoneSnapshot> pheromoneSnapshots(const PlanRequest& request, const std::vector<int>& iterations);

}  // namespace eaci_bench
