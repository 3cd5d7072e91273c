// `eaci_bench deadline`: how closely a planning-time limit is kept. On generated maps (800 x
// 800 by default, the largest of `scale`), EACI runs with far more iterations than the limit
// allows, stopped by the same wall-clock check the ROS node and plugin build from
// max_planning_time (asked between set-up steps and between iterations); the report gives
// the wall time of each plan against its limit.
#pragma once

#include <string>
#include <vector>

#include "map_generator.hpp"

namespace eaci_bench {

struct DeadlineOptions {
  std::vector<int> sizes = {800};
  std::vector<MapKind> kinds = {MapKind::kRooms, MapKind::kClutter};
  std::vector<double> limits_s = {0.1, 0.25, 0.5, 1.0, 2.0};
  int runs = 3;                 // map seeds per kind and size
  int threads = 1;              // threads per plan (0 = all cores)
  std::string out_dir = "out/bench";
  std::string command_line;
};

int runDeadlineCommand(const DeadlineOptions& options);

}  // namespace eaci_bench
