// eaci_bench: the study harness (studies.hpp). Each study appends its records (record.hpp) to
// OUT/<command>.jsonl; scripts/bench_report.py makes docs/benchmarks.md's tables and figures
// from them. `map` writes one generated map as a map_server map (for move_base).

#include <algorithm>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "eaci/planner/parameter_file.hpp"
#include "map_command.hpp"
#include "record.hpp"
#include "studies.hpp"

namespace {

using eaci_bench::MapKind;

std::vector<MapKind> parseKinds(const std::vector<std::string>& texts, std::vector<MapKind> defaults) {
  if (texts.empty()) return defaults;
  std::vector<MapKind> kinds;
  for (const std::string& text : texts) {
    MapKind kind;
    if (!eaci_bench::parseMapKind(text, kind)) throw std::invalid_argument("unknown map kind '" + text + "'");
    kinds.push_back(kind);
  }
  return kinds;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"eaci_bench: the EACI paper's tables, parameter sweeps, scaling, time limits, cost maps and "
               "MovingAI scenarios, as JSON Lines records (OUT/<command>.jsonl)"};
  app.require_subcommand(1);
  std::string out_dir = "out/bench";
  std::vector<std::string> kinds;
  const auto kindsOption = [&](CLI::App* cmd) { cmd->add_option("--kinds", kinds, "map kinds: rooms, clutter, maze")->delimiter(','); };

  eaci_bench::PaperOptions paper;
  for (const std::string name : {"paper", "sweep"}) {
    CLI::App* cmd = app.add_subcommand(name, name == "paper" ? "the paper's Tables 1-3 on its maps (corner cutting allowed)"
                                                             : "the paper's parameter studies (Figs 11-14) and ACO's rho and tau0");
    cmd->add_option("--maps", paper.maps_dir, "directory with the paper's maps and paper_maps.json")->required();
    cmd->add_option("--runs", paper.runs, "seeds 1..runs per map, planner and value")->check(CLI::Range(1, 10000));
    cmd->add_option("--threads", paper.threads, "threads per plan (0 = all cores)")->check(CLI::Range(0, 1024));
  }

  eaci_bench::FrontOptions front;
  CLI::App* front_cmd = app.add_subcommand("front", "the paper's four maps, length against total corner angle: the exact "
                                                    "(cell, heading) search for a sweep of turn_cost, the whole exact front, "
                                                    "EACI's routes (corner cutting allowed)");
  front_cmd->add_option("--maps", front.maps_dir, "directory with the paper's maps and paper_maps.json")->required();
  front_cmd->add_option("--runs", front.runs, "EACI seeds 1..runs per map and island strategy")->check(CLI::Range(1, 10000));
  front_cmd->add_option("--threads", front.threads, "threads per EACI plan (0 = all cores)")->check(CLI::Range(0, 1024));
  front_cmd->add_option("--turn-costs", front.turn_costs, "turn_cost values (per radian) of the exact search")
      ->delimiter(',')->check(CLI::Range(0.0, 1e6));
  front_cmd->add_option("--eaci-turn-costs", front.eaci_turn_costs, "turn_cost values (per radian) EACI runs with")
      ->delimiter(',')->check(CLI::Range(0.0, 1e6));

  eaci_bench::GeneratedOptions scale, deadline;
  deadline.sizes = {800};
  deadline.runs = 3;
  CLI::App* scale_cmd = app.add_subcommand("scale", "generated maps of growing size (corner cutting forbidden)");
  scale_cmd->add_option("--sizes", scale.sizes, "map sizes (cells per side)")->delimiter(',')->check(CLI::Range(6, 4096));
  kindsOption(scale_cmd);
  scale_cmd->add_option("--runs", scale.runs, "seeds per case (0 = 5 up to 400 cells, else 3)")->check(CLI::Range(0, 1000));
  scale_cmd->add_option("--budget-s", scale.budget_s, "wall-time cap of one colony run (s)")->check(CLI::PositiveNumber);

  CLI::App* deadline_cmd = app.add_subcommand("deadline", "wall time of a plan against its time limit (max_planning_time)");
  deadline_cmd->add_option("--sizes", deadline.sizes, "map sizes (cells per side)")->delimiter(',')->check(CLI::Range(6, 4096));
  kindsOption(deadline_cmd);
  deadline_cmd->add_option("--limits-s", deadline.limits_s, "time limits (s)")->delimiter(',')->check(CLI::PositiveNumber);
  deadline_cmd->add_option("--runs", deadline.runs, "map seeds per kind and size")->check(CLI::Range(1, 1000));
  deadline_cmd->add_option("--threads", deadline.threads, "threads per plan (0 = all cores)")->check(CLI::Range(0, 1024));

  eaci_bench::CostsOptions costs;
  CLI::App* costs_cmd = app.add_subcommand("costs", "cost-aware planning on inflated cost maps: the lab and generated "
                                                    "maps, A* and EACI with and without smoothing");
  costs_cmd->add_option("--sizes", costs.sizes, "generated map sizes (cells per side; none: --sizes 0)")->delimiter(',')
      ->check(CLI::Range(0, 4096));
  kindsOption(costs_cmd);
  costs_cmd->add_option("--runs", costs.runs, "map seeds per kind and size (0 = 20 up to 400 cells, else 10)")
      ->check(CLI::Range(0, 1000));
  costs_cmd->add_option("--lab-map", costs.lab_map, "the lab map (map_server YAML); empty: no lab runs");
  costs_cmd->add_option("--lab-seeds", costs.lab_seeds, "EACI seeds per lab start/goal pair")->check(CLI::Range(1, 1000));
  costs_cmd->add_option("--budget-s", costs.budget_s, "wall-time cap of one colony run (s)")->check(CLI::PositiveNumber);
  costs_cmd->add_flag("--quick", costs.quick, "sizes 100 and 200, 2 seeds, 2 lab seeds (about a minute)");

  eaci_bench::ScenOptions scen;
  std::string params_path;
  CLI::App* scen_cmd = app.add_subcommand("scen", "a MovingAI benchmark scenario (.scen + .map): A* and EACI per problem "
                                                  "against the file's optimal lengths (corner cutting forbidden)");
  scen_cmd->add_option("scen", scen.scen_path, "the .scen file")->required()->check(CLI::ExistingFile);
  scen_cmd->add_option("--every", scen.every, "run problems 1, 1+K, 1+2K, ... of the file")->check(CLI::Range(1, 1000000000));
  scen_cmd->add_option("--map-dir", scen.map_dir, "directory of the .map files (default: the .scen file's)");
  scen_cmd->add_option("--seeds", scen.seeds, "EACI runs per problem, seeds 1..N")->check(CLI::Range(1, 1000));
  scen_cmd->add_option("--budget-s", scen.budget_s, "wall-time cap of one EACI run (s)")->check(CLI::PositiveNumber);
  scen_cmd->add_option("--params", params_path, "EACI's parameters from this flat YAML (e.g. config/eaci_planner.yaml; "
                                                "default: the project's defaults); corner cutting stays forbidden")
      ->check(CLI::ExistingFile);

  eaci_bench::MapCommandOptions map;
  std::string map_kind = "rooms";
  std::vector<int> room_cells, door_cells;
  for (CLI::App* cmd : app.get_subcommands([](CLI::App*) { return true; }))
    cmd->add_option("--out", out_dir, "output directory (records: OUT/<command>.jsonl)");
  CLI::App* map_cmd = app.add_subcommand("map", "one generated map written as a map_server map (trinary YAML + PGM)");
  map_cmd->add_option("--kind", map_kind, "rooms, clutter or maze");
  map_cmd->add_option("--size", map.size, "cells per side")->check(CLI::Range(6, 4096));
  map_cmd->add_option("--seed", map.seed, "map seed (the next seed is tried while start and goal are not connected)");
  map_cmd->add_option("--room-cells", room_cells, "rooms: room widths MIN,MAX (cells; default 10,20)")
      ->delimiter(',')->expected(1, 2)->check(CLI::Range(1, 4096));
  map_cmd->add_option("--door-cells", door_cells, "rooms: door widths MIN,MAX (cells; default 2,3)")
      ->delimiter(',')->expected(1, 2)->check(CLI::Range(1, 4096));
  map_cmd->add_option("--corridor-cells", map.generator.corridor, "maze: corridor width (cells; default 3)")->check(CLI::Range(1, 4096));
  map_cmd->add_option("--wall-cells", map.generator.maze_wall, "maze: wall thickness (cells; default 1)")->check(CLI::Range(1, 4096));
  map_cmd->add_option("--resolution", map.resolution, "metres per cell")->check(CLI::PositiveNumber);
  map_cmd->add_option("--out", map.out_yaml, "the map's YAML (the PGM is written beside it)")->required();
  CLI11_PARSE(app, argc, argv);

  std::ostringstream command_line;
  for (int k = 0; k < argc; ++k) command_line << (k ? " " : "") << argv[k];
  try {
    if (app.got_subcommand("map")) {
      if (!eaci_bench::parseMapKind(map_kind, map.kind)) throw std::invalid_argument("unknown map kind '" + map_kind + "'");
      if (!room_cells.empty()) map.generator.room_min = room_cells.front(), map.generator.room_max = room_cells.back();
      if (!door_cells.empty()) map.generator.door_min = door_cells.front(), map.generator.door_max = door_cells.back();
      return eaci_bench::runMapCommand(map);
    }
    const std::string command = app.get_subcommands().front()->get_name();
    eaci_bench::RecordWriter out(out_dir, command, command_line.str());
    int status = 0;
    if (command == "paper") eaci_bench::runPaper(paper, out);
    if (command == "sweep") eaci_bench::runSweep(paper, out);
    if (command == "front") eaci_bench::runFront(front, out);
    if (command == "scale") {
      scale.kinds = parseKinds(kinds, scale.kinds);
      eaci_bench::runScale(scale, out);
    }
    if (command == "deadline") {
      deadline.kinds = parseKinds(kinds, deadline.kinds);
      eaci_bench::runDeadline(deadline, out);
    }
    if (command == "costs") {
      costs.kinds = parseKinds(kinds, costs.kinds);
      costs.sizes.erase(std::remove(costs.sizes.begin(), costs.sizes.end(), 0), costs.sizes.end());
      eaci_bench::runCosts(costs, out);
    }
    if (command == "scen") {
      if (!params_path.empty()) eaci::applyParameterFile(params_path, scen.parameters, params_path);
      scen.parameters.allow_corner_cutting = false;  // MovingAI's rule
      eaci::validate(scen.parameters);
      const int mismatches = eaci_bench::runScen(scen, out);
      if (mismatches > 0) std::cerr << "eaci_bench: " << mismatches << " problem(s) where A* differs from the file's optimal length\n";
      status = mismatches > 0 ? 1 : 0;
    }
    std::cout << "wrote " << out.path() << "\n";
    return status;
  } catch (const std::exception& e) {
    std::cerr << "\neaci_bench: error: " << e.what() << std::endl;
    return 2;
  }
}
