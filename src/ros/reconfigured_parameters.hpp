// The bridge between a dynamic_reconfigure EaciPlannerConfig (cfg/EaciPlanner.cfg) and the
// planner's parameters: by name, through the same text forms as the parameter server and the
// one parameter table, so the table's parsing and validation are the only ones.
#pragma once

#include <eaci_planner/EaciPlannerConfig.h>

#include <string>
#include <utility>
#include <vector>

#include "ros_parameters.hpp"

namespace eaci_ros {

using PlannerConfig = eaci_planner::EaciPlannerConfig;

// Every value of `config` by name, as text (numbers exact).
std::vector<std::pair<std::string, std::string>> configValues(const PlannerConfig& config);

// The value named `name` in `config` as text; "" when the config has no such parameter.
std::string configValue(const PlannerConfig& config, const std::string& name);

// Sets every parameter `config` holds in `params` and `options` (the others are left as they
// are) and validates the result. "" when all is well, else one sentence starting with the name
// of the first bad parameter (then `params` and `options` are partly set: use copies).
std::string applyConfig(const PlannerConfig& config, eaci::Parameters& params, RosPlannerOptions& options);

// The same for the parameters whose value in `config` differs from `previous` (the config as
// last applied): a value the config cannot hold (a seed above INT_MAX) is kept until the user
// changes that parameter.
std::string applyConfig(const PlannerConfig& config, const PlannerConfig& previous, eaci::Parameters& params,
                        RosPlannerOptions& options);

// Sets every parameter `config` holds to its value in `params` and `options` (a seed wider
// than an int, which the config cannot hold, leaves the config's).
void storeInConfig(const eaci::Parameters& params, const RosPlannerOptions& options, PlannerConfig& config);

}  // namespace eaci_ros
