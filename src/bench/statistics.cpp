#include "statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace eaci_bench {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double gapPercent(double length, double optimum) {
  if (!std::isfinite(length) || !(optimum > 0) || !std::isfinite(optimum)) return kInfinity;
  return (length / optimum - 1.0) * 100.0;
}

// The shortest route; among equally short ones the one with the least turning, then the first.
std::size_t bestRunIndex(const std::vector<RunRecord>& runs) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const bool shorter = runs[k].length < runs[best].length - kOptimumTolerance;
    const bool as_short = std::abs(runs[k].length - runs[best].length) <= kOptimumTolerance;
    if (shorter || (as_short && runs[k].total_turn_deg < runs[best].total_turn_deg)) best = k;
  }
  return best;
}

std::size_t medianRunIndex(const std::vector<RunRecord>& runs) {
  std::vector<std::size_t> order(runs.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::make_tuple(runs[a].length, runs[a].iterations_to_converge, runs[a].lost_ants_total) <
           std::make_tuple(runs[b].length, runs[b].iterations_to_converge, runs[b].lost_ants_total);
  });
  return order[(order.size() - 1) / 2];
}

}  // namespace

double mean(const std::vector<double>& values) {
  if (values.empty()) return kInfinity;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double median(std::vector<double> values) {
  if (values.empty()) return kInfinity;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double sampleStandardDeviation(const std::vector<double>& values) {
  if (values.size() < 2) return 0.0;
  const double m = mean(values);
  double sum = 0.0;
  for (double v : values) sum += (v - m) * (v - m);
  return std::sqrt(sum / static_cast<double>(values.size() - 1));
}

Summary summarize(const std::vector<RunRecord>& runs, double optimum) {
  Summary s;
  s.runs = static_cast<int>(runs.size());
  if (runs.empty()) return s;
  std::vector<double> lengths, iterations, iterations_run, lost, times, cpu_times, times_to_best;
  for (const RunRecord& run : runs) {
    iterations.push_back(run.iterations_to_converge);
    iterations_run.push_back(run.iterations_run);
    lost.push_back(static_cast<double>(run.lost_ants_total));
    times.push_back(run.time_ms);
    cpu_times.push_back(run.cpu_ms);
    times_to_best.push_back(run.time_to_best_ms);
    s.interrupted_runs += run.interrupted ? 1 : 0;
    s.stopped_early_runs += run.stopped_early ? 1 : 0;
    if (!run.success) continue;
    ++s.successes;
    lengths.push_back(run.length);
    if (std::isfinite(optimum) && std::abs(run.length - optimum) < kOptimumTolerance) ++s.optimal_runs;
  }
  s.success_rate = static_cast<double>(s.successes) / s.runs;
  s.avg_length = mean(lengths);
  s.best_length = lengths.empty() ? kInfinity : *std::min_element(lengths.begin(), lengths.end());
  s.worst_length = lengths.empty() ? kInfinity : *std::max_element(lengths.begin(), lengths.end());
  s.std_length = sampleStandardDeviation(lengths);
  s.avg_iterations = mean(iterations);
  s.avg_iterations_run = mean(iterations_run);
  s.avg_lost_ants = mean(lost);
  s.avg_time_ms = mean(times);
  s.median_time_ms = median(times);
  s.median_cpu_ms = median(cpu_times);
  s.avg_time_to_best_ms = mean(times_to_best);
  s.median_time_to_best_ms = median(times_to_best);
  s.best_run_index = bestRunIndex(runs);
  s.median_run_index = medianRunIndex(runs);
  s.best_route_turn_deg = runs[s.best_run_index].total_turn_deg;
  s.avg_gap_pct = gapPercent(s.avg_length, optimum);
  s.best_gap_pct = gapPercent(s.best_length, optimum);
  s.worst_gap_pct = gapPercent(s.worst_length, optimum);
  return s;
}

}  // namespace eaci_bench
