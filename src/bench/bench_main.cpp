// eaci_bench: reproduces the paper's Tables 1-3 (`paper`), its parameter studies and the
// classic ACO evaporation study (`sweep`), and measures speed and memory on generated maps
// of growing size (`scale`), how closely a planning-time limit is kept (`deadline`), and
// cost-aware planning on inflated cost maps beside A* (`costs`), and runs MovingAI benchmark
// scenarios against their optimal lengths (`scen`).
// Each of those writes JSON, CSV and Markdown into --out; `map` writes one generated map as a
// map_server map (for move_base).

#include <algorithm>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "eaci/planner/parameter_file.hpp"

#include "costs.hpp"
#include "deadline.hpp"
#include "map_command.hpp"
#include "paper_tables.hpp"
#include "scale.hpp"
#include "scen.hpp"
#include "sweeps.hpp"

namespace {

std::string joinArguments(int argc, char** argv) {
  std::ostringstream s;
  for (int k = 0; k < argc; ++k) s << (k ? " " : "") << argv[k];
  return s.str();
}

void addPaperCommand(CLI::App& app, eaci_bench::PaperOptions& o) {
  CLI::App* cmd = app.add_subcommand("paper", "the paper's Tables 1-3 on its maps (corner cutting allowed)");
  cmd->add_option("--maps", o.maps_dir, "directory with paper-20x20.txt ... paper-50x50.txt")->required();
  cmd->add_option("--runs", o.runs, "seeds 1..runs per map and algorithm")->check(CLI::Range(1, 10000));
  cmd->add_option("--out", o.out_dir, "output directory");
  cmd->add_option("--threads", o.threads, "threads per plan (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--snapshots", o.snapshot_iterations, "iterations of the pheromone snapshots (0 = initial)")
      ->delimiter(',');
}

void addSweepCommand(CLI::App& app, eaci_bench::SweepOptions& o) {
  CLI::App* cmd = app.add_subcommand("sweep", "the paper's parameter studies (Figs 11-14) and ACO's rho");
  cmd->add_option("--maps", o.maps_dir, "directory with the paper's maps")->required();
  cmd->add_option("--runs", o.runs, "seeds 1..runs per value")->check(CLI::Range(1, 10000));
  cmd->add_option("--out", o.out_dir, "output directory");
  cmd->add_option("--threads", o.threads, "threads per plan (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--eaci-maps", o.eaci_maps, "paper maps for the EACI sweeps")->delimiter(',');
  cmd->add_option("--strategies", o.strategies, "island strategies (paper, geodesic)")->delimiter(',');
}

void addScaleCommand(CLI::App& app, eaci_bench::ScaleOptions& o, std::vector<std::string>& kinds) {
  CLI::App* cmd = app.add_subcommand("scale", "generated maps of growing size (corner cutting forbidden)");
  cmd->add_option("--sizes", o.sizes, "map sizes (cells per side)")->delimiter(',')->check(CLI::Range(6, 4096));
  cmd->add_option("--kinds", kinds, "map kinds: rooms, clutter, maze")->delimiter(',');
  cmd->add_option("--runs", o.runs, "seeds per case (0 = 5 up to 400 cells, else 3)")->check(CLI::Range(0, 1000));
  cmd->add_option("--out", o.out_dir, "output directory");
  cmd->add_option("--budget-s", o.budget_s, "wall-time cap of one colony run (s)")->check(CLI::PositiveNumber);
  cmd->add_option("--slow-run-s", o.slow_run_s, "a planner slower than this runs for the first seed only (s)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--early-stop", o.early_stop_iterations, "early_stop_iterations of the early-stopping EACI")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--example-max-size", o.example_max_size, "store maps and routes up to this size");
}

void addDeadlineCommand(CLI::App& app, eaci_bench::DeadlineOptions& o, std::vector<std::string>& kinds) {
  CLI::App* cmd = app.add_subcommand("deadline", "wall time of a plan against its time limit (max_planning_time)");
  cmd->add_option("--sizes", o.sizes, "map sizes (cells per side)")->delimiter(',')->check(CLI::Range(6, 4096));
  cmd->add_option("--kinds", kinds, "map kinds: rooms, clutter, maze")->delimiter(',');
  cmd->add_option("--limits-s", o.limits_s, "time limits (s)")->delimiter(',')->check(CLI::PositiveNumber);
  cmd->add_option("--runs", o.runs, "map seeds per kind and size")->check(CLI::Range(1, 1000));
  cmd->add_option("--threads", o.threads, "threads per plan (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--out", o.out_dir, "output directory");
}

void addCostsCommand(CLI::App& app, eaci_bench::CostsOptions& o, std::vector<std::string>& kinds) {
  CLI::App* cmd = app.add_subcommand("costs", "cost-aware planning on inflated cost maps: the lab and generated maps, "
                                              "A* and EACI with and without smoothing");
  cmd->add_option("--sizes", o.sizes, "generated map sizes (cells per side; none: --sizes 0)")->delimiter(',')
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--kinds", kinds, "map kinds: rooms, clutter, maze")->delimiter(',');
  cmd->add_option("--runs", o.runs, "map seeds per kind and size (0 = 20 up to 400 cells, else 10)")->check(CLI::Range(0, 1000));
  cmd->add_option("--lab-map", o.lab_map, "the lab map (map_server YAML); empty: no lab runs");
  cmd->add_option("--lab-seeds", o.lab_seeds, "EACI seeds per lab start/goal pair")->check(CLI::Range(1, 1000));
  cmd->add_option("--budget-s", o.budget_s, "wall-time cap of one colony run (s)")->check(CLI::PositiveNumber);
  cmd->add_flag("--quick", o.quick, "sizes 100 and 200, 2 seeds, 2 lab seeds (about a minute)");
  cmd->add_option("--example-max-size", o.example_max_size, "store cost maps and routes of seed 1 up to this size");
  cmd->add_option("--out", o.out_dir, "output directory");
}

void addScenCommand(CLI::App& app, eaci_bench::ScenOptions& o) {
  CLI::App* cmd = app.add_subcommand("scen", "a MovingAI benchmark scenario (.scen + .map): A* and EACI per problem "
                                             "against the file's optimal lengths (corner cutting forbidden)");
  cmd->add_option("scen", o.scen_path, "the .scen file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--every", o.every, "run problems 1, 1+K, 1+2K, ... of the file")->check(CLI::Range(1, 1000000000));
  cmd->add_option("--map-dir", o.map_dir, "directory of the .map files (default: the .scen file's)");
  cmd->add_option("--seeds", o.seeds, "EACI runs per problem, seeds 1..N")->check(CLI::Range(1, 1000));
  cmd->add_option("--budget-s", o.budget_s, "wall-time cap of one EACI run (s)")->check(CLI::PositiveNumber);
  cmd->add_option("--params", o.params_path, "EACI's parameters from this flat YAML (e.g. config/eaci_planner.yaml; "
                                             "default: the project's defaults); corner cutting stays forbidden")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", o.out_dir, "output directory");
}

// --room-cells and --door-cells: "MIN,MAX" or one width for both.
void setWidthRange(const std::vector<int>& widths, int& min, int& max) {
  if (widths.empty()) return;
  min = widths.front();
  max = widths.back();
}

void addMapCommand(CLI::App& app, eaci_bench::MapCommandOptions& o, std::string& kind,
                   std::vector<int>& room_cells, std::vector<int>& door_cells) {
  CLI::App* cmd = app.add_subcommand("map", "one generated map written as a map_server map (trinary YAML + PGM)");
  cmd->add_option("--kind", kind, "rooms, clutter or maze");
  cmd->add_option("--size", o.size, "cells per side")->check(CLI::Range(6, 4096));
  cmd->add_option("--seed", o.seed, "map seed (the next seed is tried while start and goal are not connected)");
  cmd->add_option("--room-cells", room_cells, "rooms: room widths MIN,MAX (cells; default 10,20)")
      ->delimiter(',')->expected(1, 2)->check(CLI::Range(1, 4096));
  cmd->add_option("--door-cells", door_cells, "rooms: door widths MIN,MAX (cells; default 2,3)")
      ->delimiter(',')->expected(1, 2)->check(CLI::Range(1, 4096));
  cmd->add_option("--corridor-cells", o.generator.corridor, "maze: corridor width (cells; default 3)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--wall-cells", o.generator.maze_wall, "maze: wall thickness (cells; default 1)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--resolution", o.resolution, "metres per cell")->check(CLI::PositiveNumber);
  cmd->add_option("--out", o.out_yaml, "the map's YAML (the PGM is written beside it)")->required();
}

// Map kinds named on the command line, or the defaults when none were.
std::vector<eaci_bench::MapKind> parseKinds(const std::vector<std::string>& texts,
                                            std::vector<eaci_bench::MapKind> defaults) {
  if (texts.empty()) return defaults;
  std::vector<eaci_bench::MapKind> kinds;
  for (const std::string& text : texts) {
    eaci_bench::MapKind kind;
    if (!eaci_bench::parseMapKind(text, kind)) throw std::invalid_argument("unknown map kind '" + text + "'");
    kinds.push_back(kind);
  }
  return kinds;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"eaci_bench: the EACI paper's benchmarks, parameter sweeps, and scaling"};
  app.require_subcommand(1);
  eaci_bench::PaperOptions paper;
  eaci_bench::SweepOptions sweep;
  eaci_bench::ScaleOptions scale;
  eaci_bench::DeadlineOptions deadline;
  eaci_bench::CostsOptions costs;
  eaci_bench::MapCommandOptions map;
  std::vector<std::string> kinds;
  std::string map_kind = "rooms";
  std::vector<int> room_cells, door_cells;
  addPaperCommand(app, paper);
  addSweepCommand(app, sweep);
  addScaleCommand(app, scale, kinds);
  addDeadlineCommand(app, deadline, kinds);
  addCostsCommand(app, costs, kinds);
  addMapCommand(app, map, map_kind, room_cells, door_cells);
  eaci_bench::ScenOptions scen;
  addScenCommand(app, scen);
  CLI11_PARSE(app, argc, argv);

  const std::string command_line = joinArguments(argc, argv);
  try {
    if (app.got_subcommand("paper")) {
      paper.command_line = command_line;
      return eaci_bench::runPaperCommand(paper);
    }
    if (app.got_subcommand("sweep")) {
      sweep.command_line = command_line;
      return eaci_bench::runSweepCommand(sweep);
    }
    if (app.got_subcommand("deadline")) {
      deadline.command_line = command_line;
      deadline.kinds = parseKinds(kinds, deadline.kinds);
      return eaci_bench::runDeadlineCommand(deadline);
    }
    if (app.got_subcommand("costs")) {
      costs.command_line = command_line;
      costs.kinds = parseKinds(kinds, costs.kinds);
      costs.sizes.erase(std::remove(costs.sizes.begin(), costs.sizes.end(), 0), costs.sizes.end());
      return eaci_bench::runCostsCommand(costs);
    }
    if (app.got_subcommand("scen")) {
      scen.command_line = command_line;
      if (!scen.params_path.empty()) eaci::applyParameterFile(scen.params_path, scen.parameters, scen.params_path);
      scen.parameters.allow_corner_cutting = false;  // MovingAI's rule
      eaci::validate(scen.parameters);
      return eaci_bench::runScenCommand(scen);
    }
    if (app.got_subcommand("map")) {
      if (!eaci_bench::parseMapKind(map_kind, map.kind)) throw std::invalid_argument("unknown map kind '" + map_kind + "'");
      setWidthRange(room_cells, map.generator.room_min, map.generator.room_max);
      setWidthRange(door_cells, map.generator.door_min, map.generator.door_max);
      return eaci_bench::runMapCommand(map);
    }
    scale.command_line = command_line;
    scale.kinds = parseKinds(kinds, scale.kinds);
    return eaci_bench::runScaleCommand(scale);
  } catch (const std::exception& e) {
    std::cerr << "\neaci_bench: error: " << e.what() << std::endl;
    return 2;
  }
}
