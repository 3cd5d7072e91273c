// Summary of repeated runs of one algorithm on one map: the columns of the paper's tables.
#pragma once

#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_record.hpp"

namespace eaci_bench {

// Lengths within this of the optimum count as optimal.
constexpr double kOptimumTolerance = 1e-6;

struct Summary {
  int runs = 0;
  int successes = 0;
  int optimal_runs = 0;             // length equal to the A* optimum
  int interrupted_runs = 0;
  int stopped_early_runs = 0;
  double success_rate = 0.0;        // successes / runs
  double avg_length = 0.0;          // over successful runs (+inf if none)
  double best_length = 0.0;
  double worst_length = 0.0;
  double std_length = 0.0;          // sample standard deviation (n - 1) over successful runs
  double avg_iterations = 0.0;      // iterations_to_converge, over all runs
  double avg_iterations_run = 0.0;
  double avg_lost_ants = 0.0;       // lost_ants_total, over all runs
  double best_route_turn_deg = 0.0; // total corner angle of the best run's route
  double avg_time_ms = 0.0;
  double median_time_ms = 0.0;
  double median_cpu_ms = 0.0;
  double avg_time_to_best_ms = 0.0;
  double median_time_to_best_ms = 0.0;
  double avg_gap_pct = 0.0;         // (avg_length / optimum - 1) * 100
  double best_gap_pct = 0.0;
  double worst_gap_pct = 0.0;
  std::size_t best_run_index = 0;   // the shortest route (least turning, then first, on ties)
  std::size_t median_run_index = 0; // the median run by (length, iterations, lost ants)
};

// Every field under its own name; a non-finite number (no successful run, no optimum) comes out as null.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Summary, runs, successes, optimal_runs, interrupted_runs, stopped_early_runs,
                                   success_rate, avg_length, best_length, worst_length, std_length, avg_iterations,
                                   avg_iterations_run, avg_lost_ants, best_route_turn_deg, avg_time_ms,
                                   median_time_ms, median_cpu_ms, avg_time_to_best_ms, median_time_to_best_ms,
                                   avg_gap_pct, best_gap_pct, worst_gap_pct, best_run_index, median_run_index)

double mean(const std::vector<double>& values);
double median(std::vector<double> values);
double sampleStandardDeviation(const std::vector<double>& values);

// optimum <= 0 or infinite: no gaps.
Summary summarize(const std::vector<RunRecord>& runs, double optimum);

}  // namespace eaci_bench
