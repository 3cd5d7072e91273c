// The dynamic_reconfigure config (cfg/EaciPlanner.cfg) against the one parameter table: the same
// names, defaults and ranges; values set by name take effect, bad ones are named, and the values
// in force are written back. No rosmaster needed.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "planner_configuration.hpp"

namespace {

using eaci_ros::PlannerConfig;
using eaci_ros::RosPlannerOptions;

std::set<std::string> configNames() {
  std::set<std::string> names;
  for (const auto& [name, text] : eaci_ros::configTexts(PlannerConfig::__getDefault__())) names.insert(name);
  return names;
}

// The error of applying `config` over the robot-ready defaults.
template <class Change>
std::string errorWith(Change change) {
  PlannerConfig config = PlannerConfig::__getDefault__();
  change(config);
  eaci::Parameters params = eaci_ros::rosDefaultParameters();
  RosPlannerOptions options;
  return eaci_ros::applyConfig(config, nullptr, params, options);
}

}  // namespace

// The robot's group holds what a builder sets for a robot, at most 15; the colony's group the
// colony's research parameters; nothing of the ACO and MAACO baselines, and no smoothing or
// turn-pricing variants (the CLI's).
TEST(ReconfigureConfig, TheRobotsGroupHoldsAtMostFifteenAndTheColonyItsOwn) {
  const std::set<std::string> robot = {"algorithm",   "default_tolerance", "allow_unknown",     "neutral_cost",
                                       "cost_factor", "lethal_cost",       "turn_cost",         "smooth_path",
                                       "max_planning_time", "orientation_mode", "publish_plan", "visualize_pheromone"};
  const std::set<std::string> colony = {"ants",   "max_iterations",  "alpha",        "beta",
                                        "q",      "kappa",           "islands",      "lambda",
                                        "epsilon", "island_strategy", "island_spacing_max", "region_margin",
                                        "early_stop_iterations", "stop_gap", "seed", "threads"};
  std::map<std::string, std::set<std::string>> groups;
  dynamic_reconfigure::ConfigDescription description = PlannerConfig::__getDescriptionMessage__();
  for (const auto& group : description.groups)
    for (const auto& parameter : group.parameters) groups[group.name].insert(parameter.name);
  EXPECT_EQ(groups["robot"], robot);
  EXPECT_EQ(groups["colony"], colony);
  EXPECT_LE(robot.size(), 15u);
  std::set<std::string> all = robot;
  all.insert(colony.begin(), colony.end());
  EXPECT_EQ(configNames(), all);
  for (const std::string& name : configNames()) {
    EXPECT_EQ(name.rfind("aco_", 0), std::string::npos) << name;
    EXPECT_EQ(name.rfind("maaco_", 0), std::string::npos) << name;
  }
}

// Every default of the cfg is the plugin's (rosDefaultParameters(), RosPlannerOptions{}).
TEST(ReconfigureConfig, DefaultsAreTheRobotReadyOnes) {
  const eaci::Parameters robot = eaci_ros::rosDefaultParameters();
  const RosPlannerOptions options;
  for (const auto& [name, text] : eaci_ros::configTexts(PlannerConfig::__getDefault__()))
    EXPECT_EQ(text, eaci_ros::valueText(eaci_ros::rosParameterValue(robot, options, name))) << name;
  EXPECT_EQ(PlannerConfig::__getDefault__().orientation_mode, 1);  // global_planner's Forward
}

// The cfg's min and max are valid values (dynamic_reconfigure clamps into them), except where
// the valid range is open at that end (then the bound itself is named as bad).
TEST(ReconfigureConfig, TheRangesAreTheValidationsRanges) {
  const std::set<std::string> open_at_min = {"q", "kappa", "lambda", "neutral_cost"};
  const std::set<std::string> words = {"algorithm", "island_strategy"};
  for (const PlannerConfig* bound : {&PlannerConfig::__getMin__(), &PlannerConfig::__getMax__()}) {
    const bool at_min = bound == &PlannerConfig::__getMin__();
    for (const auto& [name, text] : eaci_ros::configTexts(*bound)) {
      if (words.count(name) || text == "inf") continue;  // no bound
      eaci::Parameters params = eaci_ros::rosDefaultParameters();
      RosPlannerOptions options;
      eaci_ros::setRosParameter(params, options, name, text);
      const std::string error = eaci_ros::rosValidationError(params, options);
      if (at_min && open_at_min.count(name)) {
        EXPECT_EQ(error.rfind(name, 0), 0u) << name << " = " << text << ": " << error;
      } else {
        EXPECT_EQ(error, "") << name << " = " << text;
      }
    }
  }
  EXPECT_EQ(PlannerConfig::__getMin__().ants, 1);
  EXPECT_EQ(PlannerConfig::__getMin__().islands, 2);
  EXPECT_EQ(PlannerConfig::__getMax__().lethal_cost, 255);
  EXPECT_EQ(PlannerConfig::__getMax__().orientation_mode, 6);
}

TEST(ReconfigureConfig, EveryValueSetsItsParameterAndTheOthersStay) {
  eaci::Parameters params = eaci_ros::rosDefaultParameters();
  RosPlannerOptions options;
  options.occupied_threshold = 42;  // not in the config: kept
  options.robot_radius = 0.3;
  PlannerConfig config = PlannerConfig::__getDefault__();
  config.cost_factor = 1.0;
  config.neutral_cost = 20.0;
  config.lethal_cost = 200;
  config.allow_unknown = false;
  config.ants = 7;
  config.island_strategy = "paper";
  config.algorithm = "astar";
  config.default_tolerance = 0.3;
  config.publish_plan = false;
  config.visualize_pheromone = true;
  config.orientation_mode = 5;
  EXPECT_EQ(eaci_ros::applyConfig(config, nullptr, params, options), "");
  EXPECT_EQ(params.cost_factor, 1.0);
  EXPECT_EQ(params.neutral_cost, 20.0);
  EXPECT_EQ(params.lethal_cost, 200);
  EXPECT_FALSE(params.allow_unknown);
  EXPECT_EQ(params.ants, 7);
  EXPECT_EQ(params.island_strategy, eaci::IslandStrategy::kPaper);
  EXPECT_EQ(params.kappa, 0.9);
  EXPECT_FALSE(params.allow_corner_cutting);
  EXPECT_EQ(options.algorithm, eaci::Algorithm::kAStar);
  EXPECT_EQ(options.default_tolerance, 0.3);
  EXPECT_FALSE(options.publish_plan);
  EXPECT_TRUE(options.visualize_pheromone);
  EXPECT_EQ(options.orientation_mode, eaci::OrientationMode::kLeftward);
  EXPECT_EQ(options.occupied_threshold, 42);
  EXPECT_EQ(options.robot_radius, 0.3);
}

// Only what differs from the config in force is set, and the changes are listed.
TEST(ReconfigureConfig, OnlyTheChangedValuesAreSet) {
  PlannerConfig in_force = PlannerConfig::__getDefault__();
  eaci::Parameters params = eaci_ros::rosDefaultParameters();
  params.seed = 1ull << 40;  // wider than the config's int: kept while the config's seed stays
  RosPlannerOptions options;
  PlannerConfig config = in_force;
  config.ants = 12;
  config.stop_gap = 0.05;
  std::string changes;
  EXPECT_EQ(eaci_ros::applyConfig(config, &in_force, params, options, &changes), "");
  EXPECT_EQ(changes, "ants 12, stop_gap 0.05");
  EXPECT_EQ(params.ants, 12);
  EXPECT_EQ(params.seed, 1ull << 40);
}

TEST(ReconfigureConfig, ABadValueIsNamedWithItsValueAndWhy) {
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.kappa = 0.0; }), "kappa must be in (0, 1.3] (got 0)");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.algorithm = "dijkstra"; }),
            "algorithm must be eaci or astar (got 'dijkstra'; the paper's aco and maaco baselines run in eaci_plan and "
            "eaci_bench)");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.algorithm = "maaco"; }).rfind("algorithm must be eaci or astar", 0), 0u);
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.lethal_cost = 300; }),
            "lethal_cost must be in 1..255, the costmap cost at or above which a cell is an obstacle (got 300)");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.orientation_mode = 7; }).rfind("orientation_mode: '7' is not one of", 0),
            0u);
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.island_strategy = "random"; }),
            "island_strategy: 'random' is not one of: geodesic, paper");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.seed = -1; }),
            "seed: '-1' is not an integer in 0..18446744073709551615");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.default_tolerance = -0.1; }),
            "default_tolerance must be a distance >= 0 (got -0.1)");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.max_planning_time = -1; }),
            "max_planning_time must be in [0, 3600] seconds, 0 = no limit (got -1)");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.max_planning_time = 1e10; }),  // its deadline would overflow
            "max_planning_time must be in [0, 3600] seconds, 0 = no limit (got 1e+10)");
}

// A rejected reconfigure writes the values in force back into the config it answers with.
TEST(ReconfigureConfig, TheValuesInForceAreWrittenBack) {
  eaci::Parameters params = eaci_ros::rosDefaultParameters();
  params.kappa = 0.5;
  params.ants = 12;
  params.allow_unknown = false;
  params.island_strategy = eaci::IslandStrategy::kPaper;
  RosPlannerOptions options;
  options.algorithm = eaci::Algorithm::kAStar;
  options.orientation_mode = eaci::OrientationMode::kInterpolate;
  options.max_planning_time = 0.75;
  PlannerConfig config = PlannerConfig::__getDefault__();
  config.kappa = 0.0;  // rejected: the values in force go back
  eaci::Parameters tried = params;
  RosPlannerOptions tried_options = options;
  EXPECT_EQ(eaci_ros::applyConfig(config, nullptr, tried, tried_options), "kappa must be in (0, 1.3] (got 0)");
  eaci_ros::storeInConfig(params, options, config);
  EXPECT_EQ(config.kappa, 0.5);
  EXPECT_EQ(config.ants, 12);
  EXPECT_FALSE(config.allow_unknown);
  EXPECT_EQ(config.island_strategy, "paper");
  EXPECT_EQ(config.algorithm, "astar");
  EXPECT_EQ(config.orientation_mode, 2);  // global_planner's Interpolate
  EXPECT_EQ(config.max_planning_time, 0.75);
  params.seed = 1ull << 40;  // wider than the config's int: the config's stays
  config.seed = 3;
  eaci_ros::storeInConfig(params, options, config);
  EXPECT_EQ(config.seed, 3);
}
