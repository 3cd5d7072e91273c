// The dynamic_reconfigure config (cfg/EaciPlanner.cfg) against the one parameter table: the same
// names and defaults, values set by name take effect, bad ones are named; and the ROS
// parameter helpers. No rosmaster needed.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "reconfigured_parameters.hpp"
#include "ros_parameters.hpp"

namespace {

using eaci_ros::PlannerConfig;
using eaci_ros::RosPlannerOptions;

std::set<std::string> configNames() {
  std::set<std::string> names;
  for (const auto& [name, text] : eaci_ros::configValues(PlannerConfig::__getDefault__())) names.insert(name);
  return names;
}

}  // namespace

TEST(ReconfigureConfig, HoldsEveryTableParameterButCornerCuttingAndTheRunTimeRosOptions) {
  std::set<std::string> expected;
  for (const std::string& name : eaci::parameterNames())
    if (name != "allow_corner_cutting") expected.insert(name);  // never on a robot
  for (const char* option : {"algorithm", "default_tolerance", "max_planning_time", "publish_plan",
                             "visualize_pheromone", "orientation_mode"})
    expected.insert(option);
  EXPECT_EQ(configNames(), expected);
}

TEST(ReconfigureConfig, DefaultsAreTheRobotReadyOnes) {
  const PlannerConfig config = PlannerConfig::__getDefault__();
  const eaci::Parameters paper = eaci_ros::rosDefaultParameters();  // the paper's colony, robot-ready
  EXPECT_EQ(config.ants, paper.ants);
  EXPECT_EQ(config.max_iterations, paper.max_iterations);
  EXPECT_EQ(config.alpha, paper.alpha);
  EXPECT_EQ(config.beta, paper.beta);
  EXPECT_EQ(config.q, paper.q);
  EXPECT_EQ(config.kappa, paper.kappa);
  EXPECT_EQ(config.islands, paper.islands);
  EXPECT_EQ(config.lambda, paper.lambda);
  EXPECT_EQ(config.epsilon, paper.epsilon);
  EXPECT_EQ(config.aco_rho, paper.aco_rho);
  EXPECT_EQ(config.aco_tau0, paper.aco_tau0);
  EXPECT_EQ(config.island_strategy, eaci::toString(paper.island_strategy));
  EXPECT_EQ(config.island_spacing_max, paper.island_spacing_max);
  EXPECT_EQ(config.region_margin, paper.region_margin);
  EXPECT_EQ(config.early_stop_iterations, paper.early_stop_iterations);
  EXPECT_EQ(static_cast<std::uint64_t>(config.seed), paper.seed);
  EXPECT_EQ(config.threads, paper.threads);
  EXPECT_EQ(config.neutral_cost, paper.neutral_cost);
  EXPECT_EQ(config.cost_factor, paper.cost_factor);
  EXPECT_EQ(config.lethal_cost, paper.lethal_cost);
  // The ROS layer's own defaults, as navfn and global_planner: unknown cells are free; and the
  // robot drives the smoothed route.
  EXPECT_TRUE(config.allow_unknown);
  EXPECT_TRUE(config.smooth_path);
  const RosPlannerOptions ros;
  EXPECT_EQ(config.algorithm, eaci::toString(ros.algorithm));
  EXPECT_EQ(config.default_tolerance, ros.default_tolerance);
  EXPECT_EQ(config.max_planning_time, ros.max_planning_time);
  EXPECT_EQ(config.publish_plan, ros.publish_plan);
  EXPECT_EQ(config.visualize_pheromone, ros.visualize_pheromone);
  EXPECT_EQ(config.orientation_mode, 1);  // global_planner's Forward
  EXPECT_EQ(ros.orientation_mode, eaci::OrientationMode::kForward);
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
  config.aco_rho = 0.25;
  config.ants = 7;
  config.island_strategy = "paper";
  config.algorithm = "astar";
  config.default_tolerance = 0.3;
  config.publish_plan = false;
  config.visualize_pheromone = true;
  config.orientation_mode = 5;
  EXPECT_EQ(eaci_ros::applyConfig(config, params, options), "");
  EXPECT_EQ(params.cost_factor, 1.0);
  EXPECT_EQ(params.neutral_cost, 20.0);
  EXPECT_EQ(params.lethal_cost, 200);
  EXPECT_FALSE(params.allow_unknown);
  EXPECT_EQ(params.aco_rho, 0.25);
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

TEST(ReconfigureConfig, ABadValueIsNamed) {
  auto errorWith = [](auto change) {
    PlannerConfig config = PlannerConfig::__getDefault__();
    change(config);
    eaci::Parameters params = eaci_ros::rosDefaultParameters();
    RosPlannerOptions options;
    return eaci_ros::applyConfig(config, params, options);
  };
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.aco_rho = 1.5; }), "aco_rho must be in (0, 1] (got 1.5)");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.algorithm = "dijkstra"; }),
            "algorithm must be eaci, aco or astar (got 'dijkstra')");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.lethal_cost = 300; }).rfind("lethal_cost must be in 1..255", 0), 0u);
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.orientation_mode = 7; }).rfind("orientation_mode: '7' is not one of", 0),
            0u);
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.island_strategy = "random"; }).rfind("island_strategy: 'random'", 0), 0u);
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.seed = -1; }).rfind("seed: '-1'", 0), 0u);
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.default_tolerance = -0.1; }),
            "default_tolerance must be a distance >= 0 (got -0.1)");
  EXPECT_EQ(errorWith([](PlannerConfig& c) { c.max_planning_time = -1; }).rfind("max_planning_time must be >= 0", 0), 0u);
}

TEST(ReconfigureConfig, StoredValuesReadBack) {
  eaci::Parameters params = eaci_ros::rosDefaultParameters();
  params.aco_rho = 0.25;
  params.ants = 12;
  params.allow_unknown = false;
  params.island_strategy = eaci::IslandStrategy::kPaper;
  RosPlannerOptions options;
  options.algorithm = eaci::Algorithm::kAco;
  options.orientation_mode = eaci::OrientationMode::kInterpolate;
  options.max_planning_time = 0.75;
  PlannerConfig config = PlannerConfig::__getDefault__();
  eaci_ros::storeInConfig(params, options, config);
  EXPECT_EQ(config.aco_rho, 0.25);
  EXPECT_EQ(config.ants, 12);
  EXPECT_FALSE(config.allow_unknown);
  EXPECT_EQ(config.island_strategy, "paper");
  EXPECT_EQ(config.algorithm, "aco");
  EXPECT_EQ(config.orientation_mode, 2);  // global_planner's Interpolate
  EXPECT_EQ(config.max_planning_time, 0.75);
  EXPECT_EQ(eaci_ros::configValue(config, "ants"), "12");
  EXPECT_EQ(eaci_ros::configValue(config, "no_such_parameter"), "");
}

TEST(RosParameters, SentencesNameTheirParameter) {
  EXPECT_EQ(eaci_ros::parameterNamedIn("islands (N) must be in 2..100000: S and E count (got 1)"), "islands");
  EXPECT_EQ(eaci_ros::parameterNamedIn("aco_rho: 'x' is not a number"), "aco_rho");
  EXPECT_EQ(eaci_ros::parameterNamedIn("ants must be in 1..1000000 (got 0)"), "ants");
  EXPECT_EQ(eaci_ros::parameterNamedIn("max_iterations must be in 1..1000000 (got 0)"), "max_iterations");
  EXPECT_EQ(eaci_ros::parameterNamedIn("robot_radius must be a distance >= 0 (got -1)"), "robot_radius");
  EXPECT_EQ(eaci_ros::parameterNamedIn("something else"), "");
}
