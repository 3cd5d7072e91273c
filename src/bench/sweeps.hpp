// `eaci_bench sweep`: the paper's parameter studies (Figs 11-14: epsilon, lambda, N, kappa;
// tuning runs with N = 6) for EACI on the 20x20 (and 40x40) map, and the evaporation rate
// rho (and initial pheromone tau0) of the classic ACO baseline on all four maps, which the
// paper does not report.
#pragma once

#include <string>
#include <vector>

#include "eaci/planner/parameters.hpp"
#include "paper_maps.hpp"
#include "statistics.hpp"

namespace eaci_bench {

struct SweepOptions {
  std::string maps_dir;
  int runs = 20;
  std::string out_dir = "out/bench";
  int threads = 1;
  std::vector<std::string> eaci_maps = {"paper-20x20", "paper-40x40"};
  std::vector<std::string> strategies = {"paper", "geodesic"};
  std::string command_line;
};

// One parameter study: `key` takes each of `values`; `base` is set first.
struct SweepAxis {
  std::string key;      // a Parameters name (setParameter); paperSymbol(key) in the tables
  std::string figure;   // the paper's figure
  std::vector<double> values;
  std::vector<std::pair<std::string, std::string>> base;
};

struct SweepPoint {
  std::string axis;
  double value = 0.0;
  std::string map;
  std::string strategy;
  std::vector<RunRecord> runs;
  Summary summary;
};

struct RhoPoint {
  std::string map;
  double rho = 0.0;
  double tau0 = 1.0;
  std::vector<RunRecord> runs;
  Summary summary;
  PaperRow paper;  // the paper's ACO row for the map
  double iterations_ratio = 0.0;  // ours / paper
  double lost_ants_ratio = 0.0;
  bool within_factor_2 = false;   // both ratios in [0.5, 2]
};

// A swept value as setParameter reads it and the tables show it: "6" for an integer key, "0.3".
std::string parameterText(double value);

// The paper's tuning parameters: its comparison parameters (the defaults) with N = 6, corner
// cutting allowed.
eaci::Parameters paperTuningParameters();

const std::vector<SweepAxis>& eaciSweepAxes();
const std::vector<double>& acoRhoValues();
// tau0 matters as tau0 * L / Q, the size of the initial pheromone against one ant's deposit;
// 800 with Q = 100 is the common MATLAB ACO code's tau0 = 8 with Q = 1.
const std::vector<double>& acoTau0Values();

int runSweepCommand(const SweepOptions& options);

}  // namespace eaci_bench
