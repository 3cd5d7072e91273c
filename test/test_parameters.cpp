// The parameter struct: the paper's defaults, one validation, settable by name.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <limits>

#include "eaci/planner/parameters.hpp"

TEST(Parameters, DefaultsAreThePapers) {
  const eaci::Parameters p;
  EXPECT_EQ(p.ants, 50);
  EXPECT_EQ(p.max_iterations, 100);
  EXPECT_DOUBLE_EQ(p.alpha, 1.1);
  EXPECT_DOUBLE_EQ(p.beta, 7.0);
  EXPECT_DOUBLE_EQ(p.q, 100.0);
  EXPECT_DOUBLE_EQ(p.kappa, 0.9);
  EXPECT_EQ(p.islands, 9);
  EXPECT_DOUBLE_EQ(p.lambda, 3.0);
  EXPECT_DOUBLE_EQ(p.epsilon, 0.5);
  EXPECT_FALSE(p.allow_corner_cutting);
  EXPECT_EQ(p.island_strategy, eaci::IslandStrategy::kGeodesic);
  // The cost model: global_planner's defaults, unknown cells closed.
  EXPECT_DOUBLE_EQ(p.neutral_cost, 50.0);
  EXPECT_DOUBLE_EQ(p.cost_factor, 3.0);
  EXPECT_EQ(p.lethal_cost, 253);
  EXPECT_FALSE(p.allow_unknown);
  EXPECT_EQ(p.turn_cost, 0.0);  // no price on turning: routes as before issue #30
  EXPECT_EQ(p.turn_cost_unit, eaci::TurnCostUnit::kFreeCell);  // turn_cost as it is
  EXPECT_EQ(eaci::validationError(p), "");
}

TEST(Parameters, EachBadValueGetsItsOwnReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    std::function<void(eaci::Parameters&)> spoil;
    const char* mentions;
  };
  const std::vector<Case> cases = {
      {[](auto& p) { p.ants = 0; }, "ants"},
      {[](auto& p) { p.ants = -5; }, "ants"},
      {[](auto& p) { p.max_iterations = 0; }, "max_iterations"},
      {[&](auto& p) { p.alpha = nan; }, "alpha"},
      {[](auto& p) { p.alpha = -1; }, "alpha"},
      {[&](auto& p) { p.beta = inf; }, "beta"},
      {[](auto& p) { p.q = 0; }, "q must"},
      {[](auto& p) { p.kappa = 0; }, "kappa"},
      {[](auto& p) { p.kappa = 1.5; }, "kappa"},
      {[&](auto& p) { p.kappa = nan; }, "kappa"},
      {[](auto& p) { p.islands = 1; }, "islands"},
      {[](auto& p) { p.lambda = -3; }, "lambda"},
      {[&](auto& p) { p.epsilon = nan; }, "epsilon"},
      {[](auto& p) { p.aco_rho = 0; }, "aco_rho"},
      {[](auto& p) { p.aco_rho = 1.5; }, "aco_rho"},
      {[](auto& p) { p.early_stop_iterations = -1; }, "early_stop_iterations"},
      {[](auto& p) { p.stop_gap = -0.01; }, "stop_gap must be a fraction in [0, 10]"},
      {[&](auto& p) { p.stop_gap = nan; }, "stop_gap"},
      {[](auto& p) { p.stop_gap = 11; }, "stop_gap"},
      {[](auto& p) { p.threads = -1; }, "threads"},
      {[](auto& p) { p.neutral_cost = 0; }, "neutral_cost must be a number in (0, 1e6]"},
      {[&](auto& p) { p.neutral_cost = nan; }, "neutral_cost"},
      {[](auto& p) { p.cost_factor = -0.5; }, "cost_factor must be a number in [0, 1e6]"},
      {[&](auto& p) { p.cost_factor = inf; }, "cost_factor"},
      {[](auto& p) { p.lethal_cost = 0; }, "lethal_cost must be in 1..255"},
      {[](auto& p) { p.lethal_cost = 256; }, "lethal_cost"},
      {[&](auto& p) { p.turn_cost = nan; }, "turn_cost must be a number in [0, 1e6]"},
      {[](auto& p) { p.turn_cost = -0.25; }, "turn_cost must be a number in [0, 1e6]"},
      {[&](auto& p) { p.turn_cost = inf; }, "turn_cost"},
      {[](auto& p) { p.turn_cost = 2e6; }, "turn_cost"},
      {[&](auto& p) { p.smooth_tolerance = nan; }, "smooth_tolerance"},
      {[](auto& p) { p.smooth_tolerance = -0.1; }, "smooth_tolerance"},
      {[](auto& p) { p.smooth_tolerance = 1.5; }, "smooth_tolerance"},
      {[](auto& p) { p.round_corners = -1; }, "round_corners must be in 0..4"},
      {[](auto& p) { p.round_corners = 5; }, "round_corners"},
  };
  for (const auto& c : cases) {
    eaci::Parameters p;
    c.spoil(p);
    const std::string error = eaci::validationError(p);
    EXPECT_NE(error.find(c.mentions), std::string::npos) << "got: " << error;
    EXPECT_THROW(eaci::validate(p), eaci::ParameterError);
  }
}

TEST(Parameters, SetByName) {
  eaci::Parameters p;
  eaci::setParameter(p, "ants", "20");
  eaci::setParameter(p, "alpha", "1.5");
  eaci::setParameter(p, "allow_corner_cutting", "true");
  eaci::setParameter(p, "island_strategy", "paper");
  eaci::setParameter(p, "seed", "42");
  eaci::setParameter(p, "cost_factor", "0");
  eaci::setParameter(p, "allow_unknown", "yes");
  EXPECT_EQ(p.ants, 20);
  EXPECT_DOUBLE_EQ(p.alpha, 1.5);
  EXPECT_TRUE(p.allow_corner_cutting);
  EXPECT_EQ(p.seed, 42u);
  EXPECT_EQ(p.cost_factor, 0.0);
  EXPECT_TRUE(p.allow_unknown);
  eaci::setParameter(p, "smooth_path", "true");
  EXPECT_TRUE(p.smooth_path);
  eaci::setParameter(p, "stop_gap", "0.01");
  EXPECT_DOUBLE_EQ(p.stop_gap, 0.01);
  eaci::setParameter(p, "turn_cost", "0.5");
  EXPECT_EQ(p.turn_cost, 0.5);
  eaci::setParameter(p, "turn_cost_unit", "route_cell");
  EXPECT_EQ(p.turn_cost_unit, eaci::TurnCostUnit::kRouteCell);
  eaci::setParameter(p, "smooth_tolerance", "0.2");
  EXPECT_EQ(p.smooth_tolerance, 0.2);
  eaci::setParameter(p, "round_corners", "2");
  EXPECT_EQ(p.round_corners, 2);
  EXPECT_EQ(eaci::parameterNames().size(), 40u);  // 24, turn_cost(_unit), smooth_tolerance, round_corners and MAACO's 12
}

TEST(Parameters, SetByNameRejectsUnknownKeysAndMalformedValues) {
  eaci::Parameters p;
  EXPECT_THROW(eaci::setParameter(p, "antz", "20"), eaci::ParameterError);
  EXPECT_THROW(eaci::setParameter(p, "ants", "20.5"), eaci::ParameterError);
  EXPECT_THROW(eaci::setParameter(p, "ants", ""), eaci::ParameterError);
  EXPECT_THROW(eaci::setParameter(p, "ants", "99999999999999999999"), eaci::ParameterError);
  EXPECT_THROW(eaci::setParameter(p, "alpha", "1.1x"), eaci::ParameterError);
  EXPECT_THROW(eaci::setParameter(p, "allow_corner_cutting", "maybe"), eaci::ParameterError);
  EXPECT_THROW(eaci::setParameter(p, "island_strategy", "random"), eaci::ParameterError);
  try {
    eaci::setParameter(p, "turn_cost_unit", "metre");
    ADD_FAILURE() << "turn_cost_unit metre was taken";
  } catch (const eaci::ParameterError& e) {
    EXPECT_STREQ(e.what(), "turn_cost_unit: 'metre' is not one of: free_cell, route_cell");
  }
  EXPECT_THROW(eaci::setParameter(p, "seed", "-1"), eaci::ParameterError);
  // Parsed but out of range: validation's job.
  eaci::setParameter(p, "alpha", "nan");
  EXPECT_NE(eaci::validationError(p).find("alpha"), std::string::npos);
}

TEST(Parameters, EveryNameCanBeReadBack) {
  eaci::Parameters p;
  eaci::setParameter(p, "ants", "33");
  eaci::setParameter(p, "island_strategy", "paper");
  eaci::setParameter(p, "seed", "18446744073709551615");
  const auto values = eaci::parameterValues(p);
  ASSERT_EQ(values.size(), eaci::parameterNames().size());
  std::map<std::string, eaci::ParameterValue> by_name(values.begin(), values.end());
  EXPECT_EQ(std::get<std::int64_t>(by_name.at("ants")), 33);
  EXPECT_EQ(std::get<std::string>(by_name.at("island_strategy")), "paper");
  EXPECT_EQ(std::get<std::uint64_t>(by_name.at("seed")), 18446744073709551615ull);
  EXPECT_DOUBLE_EQ(std::get<double>(by_name.at("alpha")), 1.1);
}
