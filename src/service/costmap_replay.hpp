// Saving the costmap a plan was made on as a raw map (map_server mode: raw, one costmap_2d cost
// per pixel) with what `eaci_plan` needs to replay the plan offline: the planner's parameters
// as a --params file, and the request, the outcome and the replay command as comments.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "eaci/planner/parameters.hpp"
#include "eaci/planner.hpp"
#include "costmap_snapshot.hpp"
#include "plan_outcome.hpp"

namespace eaci_service {

// One plan request in the map frame and what came of it.
struct PlanRecord {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  // m
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();   // m
  double tolerance = 0.0;                           // m
  std::string outcome;  // "route: cost ..., length ..." or "failed (<outcome word>): <reason>"
};

// The summary of a plan's outcome that PlanRecord::outcome holds.
std::string describeOutcome(PlanOutcome outcome, const std::string& error, const eaci::PlanResult& result,
                            double resolution);

struct ReplayFiles {
  std::string map_yaml;     // the raw map: <directory>/<base_name>.yaml ...
  std::string map_image;    // ... and its <base_name>.pgm
  std::string params_yaml;  // <base_name>.params.yaml: every parameter (eaci::parameterYaml)
  std::string command;      // the eaci_plan command line that replays `request`
};

// "<prefix>_YYYYmmdd-HHMMSS-mmm" in local wall-clock time.
std::string timestampedName(const std::string& prefix);

// Writes the three files into `directory` (created when missing). `notes` become comment
// lines at the top of the map's YAML, followed by the request, its outcome and the replay
// command when `request` is given. Throws eaci::MapSaveError or std::runtime_error with a
// one-line reason naming the file.
ReplayFiles saveCostmapForReplay(const std::string& directory, const std::string& base_name,
                                 const CostmapSnapshot& costmap, const eaci::Parameters& params,
                                 eaci::Algorithm algorithm, const std::optional<PlanRecord>& request,
                                 const std::vector<std::string>& notes);

}  // namespace eaci_service
