// `eaci_bench costs`: cost-aware planning on inflated cost maps (issue #10 item 8). The lab map
// with the move_base config's inflation (several start/goal pairs) and generated rooms and
// clutter maps (map_generator.hpp) inflated with costmap_2d's formula; A*, A* smoothed, EACI
// and EACI smoothed on each, one thread, each plan in its own child process (forked_run.hpp).
// Per run: cost and its gap to A*'s, length, total turning, minimum clearance and mean cell cost
// of the route the robot would drive (the smoothed one when smoothing is on), the lethal and
// inscribed cells it enters, time and its ratio to A*'s on the same map, peak memory. A*'s cost
// is checked against an independent weighted Dijkstra (cost_checks.hpp) on every map.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cost_checks.hpp"
#include "eaci/grid/inflation.hpp"
#include "eaci/planner.hpp"
#include "map_generator.hpp"
#include "run_record.hpp"
#include "variant_key.hpp"

namespace eaci_bench {

// A start and goal on the lab map, metres in the map frame.
struct LabPair {
  double start_x, start_y, goal_x, goal_y;
  std::string note;
};

// The five goals of docs/ros.md's move_base runs from (0.4, 0.4), and three crossings.
std::vector<LabPair> defaultLabPairs();

struct CostsOptions {
  std::vector<int> sizes = {100, 200, 400, 800};
  std::vector<MapKind> kinds = {MapKind::kRooms, MapKind::kClutter};
  int runs = 0;               // map seeds per generated case; 0 = by size (costsSeedsFor)
  std::string lab_map = "maps/lab.yaml";  // empty: no lab runs
  int lab_seeds = 10;         // EACI seeds per lab pair (A* runs beside each)
  double budget_s = 60.0;     // a colony run stops between iterations after this long (marked capped)
  bool quick = false;         // sizes 100 and 200, 2 seeds, 2 lab seeds
  // The lab: config/costmap_common_params.yaml (inflation_radius 0.30, cost_scaling_factor 8.0)
  // and the inscribed radius costmap_2d derives from its padded footprint (0.1025 + 0.01 m).
  eaci::InflationParameters lab_inflation{0.30, 0.1125, 8.0};
  // Generated maps, in cells (resolution 1): the lab's 6-cell band and its decay per cell
  // (8 / m x 0.05 m), with an inscribed radius of 1 cell so that the generator's 3-cell doors
  // can stay open (the lab's 2.25 cells would close them).
  eaci::InflationParameters generated_inflation{6.0, 1.0, 0.4};
  // Rooms maps with doors of 3-5 cells (the scale benchmark's 2-3: a 2-cell door has no cell
  // more than 1 cell from its jambs, so this inflation would close it).
  GeneratorOptions generator{3, 5};
  int example_max_size = 200; // keep cost maps and routes of seed 1 up to this size (plots)
  std::string out_dir = "out/bench";
  std::string command_line;
};

int costsSeedsFor(int size, int requested);

struct CostVariant {
  VariantKey key = VariantKey::kAStar;
  std::string label;
  eaci::Algorithm algorithm = eaci::Algorithm::kAStar;
  bool smooth = false;
};

std::vector<CostVariant> costVariants();

struct CostRun {
  RunRecord record;            // paths dropped after the checks (kept for examples)
  RouteCheck driven;           // the route the robot would drive: smoothed_path
  double gap_pct = 0.0;        // driven.cost over A*'s cost on the same problem; +inf on failure
  double time_ratio = 0.0;     // record.time_ms over A*'s (same problem, same seed)
  double peak_rss_mb = 0.0;
  bool same_grid_route = true; // smoothed variants: the grid route equals the unsmoothed variant's
};

struct CostVariantRuns {
  CostVariant variant;
  std::vector<CostRun> runs;   // one per seed
};

// One map with one start and goal.
struct CostProblem {
  std::string name;
  std::uint64_t map_seed = 0;  // generated maps: the seed asked for and the one used
  std::uint64_t map_seed_used = 0;
  eaci::Cell start, goal;
  double astar_cost = 0.0;     // from the A* runs
  double dijkstra_cost = 0.0;  // dijkstraCost on the inflated map
  double obstacle_fraction = 0.0;
  double blocked_fraction = 0.0;  // cells >= 253 after inflation
  std::vector<CostVariantRuns> variants;
  CostBytes example_costs;     // seed-1 examples only
};

// The lab, or one kind and size of generated map.
struct CostGroup {
  std::string name;            // "lab", "rooms 200"
  bool lab = false;
  MapKind kind = MapKind::kRooms;
  int size = 0;
  double resolution = 1.0;     // metres per cell (1: clearances in cells)
  std::vector<CostProblem> problems;
  std::vector<std::string> notes;
};

int runCostsCommand(CostsOptions options);

}  // namespace eaci_bench
