// Writers for `eaci_bench costs`: JSON (every run with its checks, example cost maps with routes),
// CSV (one row per run), Markdown (the lab per start/goal pair, the generated maps per size, and
// the verdict per size against issue #10's targets).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "costs.hpp"
#include "provenance.hpp"

namespace eaci_bench {

// One planner's runs over a set of problems, summarised.
struct CostVariantSummary {
  int runs = 0;
  int successes = 0;
  int capped = 0;
  GapSummary gap;                  // driven cost over A*'s, % (failures count as +infinity)
  double median_time_ms = 0.0;
  double median_time_ratio = 0.0;  // over A*'s time on the same problem and seed
  double median_length = 0.0;      // cells
  double median_turn_deg = 0.0;
  double min_clearance = 0.0;      // cells, worst over the runs
  double median_clearance = 0.0;   // cells
  double median_mean_cell_cost = 0.0;
  int lethal_cells = 0;            // summed over the runs
  int inscribed_cells = 0;
  int routes_in_lethal = 0;        // routes entering a lethal or inscribed cell
  double max_peak_rss_mb = 0.0;
};

CostVariantSummary summarizeVariant(const std::vector<const CostProblem*>& problems, VariantKey key);

// Largest |A* cost - Dijkstra cost| / Dijkstra cost over the problems.
double worstAStarDijkstraDifference(const CostGroup& group);

nlohmann::json costsJson(const std::vector<CostGroup>& groups, const CostsOptions& options, const Provenance& provenance);
std::string costsCsv(const std::vector<CostGroup>& groups);
std::string costsMarkdown(const std::vector<CostGroup>& groups, const CostsOptions& options, const Provenance& provenance);

}  // namespace eaci_bench
