// The planner's parameters in one place, with the paper's defaults (Section 5), validated in
// one place, and settable by name (CLI --set, --params YAML, ROS): the colony's settings
// (aco/colony_parameters.hpp) and the planner's own (cost model, move rule, smoothing).
#pragma once

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "eaci/aco/colony_parameters.hpp"
#include "eaci/grid/costmap_costs.hpp"
#include "eaci/planner/parameter_text.hpp"
#include "eaci/planner/turn_cost_unit.hpp"

namespace eaci {

// The planner's configuration: the colony's settings, and the cost model, move rule and
// smoothing of every planner (A* included).
struct Parameters : ColonyParameters {
  bool allow_corner_cutting = false;  // diagonal between two corner-touching obstacles
  // The cost model of every planner (global_planner's): a move into a cell of cost c costs
  // step_length x (neutral_cost + cost_factor x c) / neutral_cost, and a route's cost, L_k, is
  // the sum. On a costmap, cells at or above lethal_cost are obstacles and the others have
  // cost c = their value; unknown cells are obstacles, or with allow_unknown passable at the
  // dearest cost (CellInterpretation::unknownCost: 252 on the costmap scale). Map files and
  // OccupancyGrids have free cells of cost 0: a route's cost is its length there.
  double neutral_cost = 50.0;
  double cost_factor = 3.0;
  int lethal_cost = kCostmapInscribed;  // costmap_2d INSCRIBED_INFLATED_OBSTACLE
  bool allow_unknown = false; // the ROS layer defaults to true, as navfn and global_planner do
  // After the search, shortcut the 8-connected route by line of sight (path/smoothing.hpp):
  // never through an obstacle, never costlier. Off for the paper's benchmarks; the ROS layer
  // turns it on.
  bool smooth_path = false;
  // With smooth_path: a shortcut may cost up to (1 + smooth_tolerance) x the stretch it replaces
  // and enter cells up to (1 + smooth_tolerance) x its costliest cell (path/smoothing.hpp). 0 =
  // never costlier, never nearer the walls; more rounds a cost-aware route's corners.
  double smooth_tolerance = 0.0;
  // With smooth_path: passes of corner rounding over the smoothed route (path/smoothing.hpp,
  // roundCorners), each cut by the smoother's rule with the corner it cuts off as the stretch
  // replaced (never much nearer the walls than the bend); each pass splits a corner's turn in two. 0 = off.
  int round_corners = 0;
  // turn_cost, the price of turning, is the colonies' too: ColonyParameters. Its unit: a free
  // cell, or the average cell of the cheapest route between start and goal
  // (planner/turn_cost_unit.hpp; plan() prices turns at turn_cost x that cell's cost).
  TurnCostUnit turn_cost_unit = TurnCostUnit::kFreeCell;
};

// The one place parameters are checked. Returns "" when valid, else a sentence.
inline std::string validationError(const Parameters& p) {
  std::ostringstream e;
  auto finite = [](double v) { return std::isfinite(v); };
  if (p.ants < 1 || p.ants > 1000000) e << "ants must be in 1..1000000 (got " << p.ants << ")";
  else if (p.max_iterations < 1 || p.max_iterations > 1000000)
    e << "max_iterations must be in 1..1000000 (got " << p.max_iterations << ")";
  else if (!finite(p.alpha) || p.alpha < 0 || p.alpha > 20) e << "alpha must be a number in [0, 20] (got " << p.alpha << ")";
  else if (!finite(p.beta) || p.beta < 0 || p.beta > 20) e << "beta must be a number in [0, 20] (got " << p.beta << ")";
  else if (!finite(p.q) || p.q <= 0) e << "q must be a positive number (got " << p.q << ")";
  else if (!finite(p.kappa) || p.kappa <= 0 || p.kappa > 1.3) e << "kappa must be in (0, 1.3] (got " << p.kappa << ")";
  else if (p.islands < 2 || p.islands > 100000) e << "islands (N) must be in 2..100000: S and E count (got " << p.islands << ")";
  else if (!finite(p.lambda) || p.lambda <= 0) e << "lambda must be a positive number (got " << p.lambda << ")";
  else if (!finite(p.epsilon) || p.epsilon < 0) e << "epsilon must be a number >= 0 (got " << p.epsilon << ")";
  else if (!finite(p.aco_rho) || p.aco_rho <= 0 || p.aco_rho > 1) e << "aco_rho must be in (0, 1] (got " << p.aco_rho << ")";
  else if (!finite(p.aco_tau0) || p.aco_tau0 <= 0) e << "aco_tau0 must be a positive number (got " << p.aco_tau0 << ")";
  else if (!finite(p.maaco_alpha) || p.maaco_alpha < 0 || p.maaco_alpha > 20)
    e << "maaco_alpha must be a number in [0, 20] (got " << p.maaco_alpha << ")";
  else if (!finite(p.maaco_q) || p.maaco_q <= 0) e << "maaco_q must be a positive number (got " << p.maaco_q << ")";
  else if (!finite(p.maaco_rho) || p.maaco_rho <= 0 || p.maaco_rho >= 1)
    e << "maaco_rho must be in (0, 1): the pheromone bounds divide by 1 - rho (got " << p.maaco_rho << ")";
  else if (!finite(p.maaco_tau0) || p.maaco_tau0 <= 0) e << "maaco_tau0 must be a positive number (got " << p.maaco_tau0 << ")";
  else if (!finite(p.maaco_q0) || p.maaco_q0 < 0 || p.maaco_q0 > 1) e << "maaco_q0 must be in [0, 1] (got " << p.maaco_q0 << ")";
  else if (!finite(p.maaco_turn_weight) || p.maaco_turn_weight < 0)
    e << "maaco_turn_weight must be a number >= 0 (got " << p.maaco_turn_weight << ")";
  else if (!finite(p.maaco_wh_max) || p.maaco_wh_max < 0 || p.maaco_wh_max > 1)
    e << "maaco_wh_max must be in [0, 1] (got " << p.maaco_wh_max << ")";
  else if (!finite(p.maaco_wh_min) || p.maaco_wh_min < 0 || p.maaco_wh_min > p.maaco_wh_max)
    e << "maaco_wh_min must be in [0, maaco_wh_max] (got " << p.maaco_wh_min << ")";
  else if (!finite(p.maaco_k_h) || p.maaco_k_h < 0) e << "maaco_k_h must be a number >= 0 (got " << p.maaco_k_h << ")";
  else if (!finite(p.neutral_cost) || p.neutral_cost <= 0 || p.neutral_cost > 1e6)
    e << "neutral_cost must be a number in (0, 1e6], the cost of a step into a free cell (got " << p.neutral_cost << ")";
  else if (!finite(p.cost_factor) || p.cost_factor < 0 || p.cost_factor > 1e6)
    e << "cost_factor must be a number in [0, 1e6], 0 = plan by length only (got " << p.cost_factor << ")";
  else if (p.lethal_cost < 1 || p.lethal_cost > 255)
    e << "lethal_cost must be in 1..255, the costmap cost at or above which a cell is an obstacle (got " << p.lethal_cost << ")";
  else if (!finite(p.island_spacing_max) || p.island_spacing_max < 0)
    e << "island_spacing_max must be a number of cells >= 0 (got " << p.island_spacing_max << ")";
  else if (p.region_margin < 0 || p.region_margin > 1000000)
    e << "region_margin must be in 0..1000000 cells, 0 = the whole map (got " << p.region_margin << ")";
  else if (p.early_stop_iterations < 0) e << "early_stop_iterations must be >= 0 (got " << p.early_stop_iterations << ")";
  else if (!finite(p.stop_gap) || p.stop_gap < 0 || p.stop_gap > 10)
    e << "stop_gap must be a fraction in [0, 10], e.g. 0.01 = within 1 % of the cheapest route (got " << p.stop_gap << ")";
  else if (!finite(p.turn_cost) || p.turn_cost < 0 || p.turn_cost > 1e6)
    e << "turn_cost must be a number in [0, 1e6], the cost of one radian of heading change between consecutive "
         "moves, 0 = no price on turning (got " << p.turn_cost << ")";
  else if (!finite(p.smooth_tolerance) || p.smooth_tolerance < 0 || p.smooth_tolerance > 1)
    e << "smooth_tolerance must be a fraction in [0, 1]: a shortcut may cost up to (1 + smooth_tolerance) x the "
         "stretch it replaces (got " << p.smooth_tolerance << ")";
  else if (p.round_corners < 0 || p.round_corners > 4)
    e << "round_corners must be in 0..4, the passes of corner rounding, 0 = off (got " << p.round_corners << ")";
  else if (p.threads < 0 || p.threads > 1024) e << "threads must be in 0..1024, 0 = all cores (got " << p.threads << ")";
  return e.str();
}

inline void validate(const Parameters& p) {
  const std::string error = validationError(p);
  if (!error.empty()) throw ParameterError(error);
}


// A parameter's value as it is: whole number, real number, boolean or word.
using ParameterValue = std::variant<std::int64_t, std::uint64_t, double, bool, std::string>;

namespace detail {

// How one named setting of a `Target` (Parameters here; the ROS layer's options too) is set from
// text and read back.
template <class Target>
struct FieldAccess {
  std::function<void(Target&, const std::string&)> set;
  std::function<ParameterValue(const Target&)> get;
};
using ParameterAccess = FieldAccess<Parameters>;

// A table row for a number or switch of `Target` (or of a base of it), read and written by the
// field's own type: int through parseInt, double through parseDouble, bool through parseBool.
template <class Target = Parameters, class Owner, class T>
FieldAccess<Target> fieldAccess(const char* name, T Owner::*field) {
  static_assert(std::is_same_v<T, int> || std::is_same_v<T, double> || std::is_same_v<T, bool>);
  return {[name, field](Target& p, const std::string& v) {
            if constexpr (std::is_same_v<T, int>) p.*field = parseInt(name, v);
            else if constexpr (std::is_same_v<T, double>) p.*field = parseDouble(name, v);
            else p.*field = parseBool(name, v);
          },
          [field](const Target& p) {
            if constexpr (std::is_same_v<T, int>) return ParameterValue{std::int64_t{p.*field}};
            else return ParameterValue{p.*field};
          }};
}

// A table row for a setting that is one of a few words (an enum with a toString()).
template <class Owner, class E>
ParameterAccess wordAccess(const char* name, E Owner::*field, std::vector<E> choices) {
  return {[name, field, choices](Parameters& p, const std::string& v) {
            std::string words;
            for (E choice : choices) {
              if (v == toString(choice)) {
                p.*field = choice;
                return;
              }
              words += (words.empty() ? "" : ", ") + std::string(toString(choice));
            }
            throw ParameterError(std::string(name) + ": '" + v + "' is not one of: " + words);
          },
          [field](const Parameters& p) { return ParameterValue{std::string(toString(p.*field))}; }};
}

// The one table of parameter names: CLI --set, --params files, ROS and the JSON output use it.
inline const std::map<std::string, ParameterAccess>& parameterTable() {
  static const std::map<std::string, ParameterAccess> table = {
      {"ants", fieldAccess("ants", &Parameters::ants)},
      {"max_iterations", fieldAccess("max_iterations", &Parameters::max_iterations)},
      {"alpha", fieldAccess("alpha", &Parameters::alpha)},
      {"beta", fieldAccess("beta", &Parameters::beta)},
      {"q", fieldAccess("q", &Parameters::q)},
      {"kappa", fieldAccess("kappa", &Parameters::kappa)},
      {"islands", fieldAccess("islands", &Parameters::islands)},
      {"lambda", fieldAccess("lambda", &Parameters::lambda)},
      {"epsilon", fieldAccess("epsilon", &Parameters::epsilon)},
      {"aco_rho", fieldAccess("aco_rho", &Parameters::aco_rho)},
      {"aco_tau0", fieldAccess("aco_tau0", &Parameters::aco_tau0)},
      {"maaco_alpha", fieldAccess("maaco_alpha", &Parameters::maaco_alpha)},
      {"maaco_q", fieldAccess("maaco_q", &Parameters::maaco_q)},
      {"maaco_rho", fieldAccess("maaco_rho", &Parameters::maaco_rho)},
      {"maaco_tau0", fieldAccess("maaco_tau0", &Parameters::maaco_tau0)},
      {"maaco_q0", fieldAccess("maaco_q0", &Parameters::maaco_q0)},
      {"maaco_turn_weight", fieldAccess("maaco_turn_weight", &Parameters::maaco_turn_weight)},
      {"maaco_wh_max", fieldAccess("maaco_wh_max", &Parameters::maaco_wh_max)},
      {"maaco_wh_min", fieldAccess("maaco_wh_min", &Parameters::maaco_wh_min)},
      {"maaco_k_h", fieldAccess("maaco_k_h", &Parameters::maaco_k_h)},
      {"maaco_candidates", wordAccess("maaco_candidates", &Parameters::maaco_candidates,
                                      {MaacoCandidates::kQuadrant, MaacoCandidates::kNearest3})},
      {"maaco_start_distance", wordAccess("maaco_start_distance", &Parameters::maaco_start_distance,
                                          {MaacoStartDistance::kWalked, MaacoStartDistance::kStraight})},
      {"maaco_bounds", wordAccess("maaco_bounds", &Parameters::maaco_bounds, {MaacoBounds::kWide, MaacoBounds::kTight})},
      {"allow_corner_cutting", fieldAccess("allow_corner_cutting", &Parameters::allow_corner_cutting)},
      {"neutral_cost", fieldAccess("neutral_cost", &Parameters::neutral_cost)},
      {"cost_factor", fieldAccess("cost_factor", &Parameters::cost_factor)},
      {"lethal_cost", fieldAccess("lethal_cost", &Parameters::lethal_cost)},
      {"smooth_path", fieldAccess("smooth_path", &Parameters::smooth_path)},
      {"smooth_tolerance", fieldAccess("smooth_tolerance", &Parameters::smooth_tolerance)},
      {"round_corners", fieldAccess("round_corners", &Parameters::round_corners)},
      {"allow_unknown", fieldAccess("allow_unknown", &Parameters::allow_unknown)},
      {"island_strategy", wordAccess("island_strategy", &Parameters::island_strategy,
                                     {IslandStrategy::kGeodesic, IslandStrategy::kPaper})},
      {"island_spacing_max", fieldAccess("island_spacing_max", &Parameters::island_spacing_max)},
      {"region_margin", fieldAccess("region_margin", &Parameters::region_margin)},
      {"early_stop_iterations", fieldAccess("early_stop_iterations", &Parameters::early_stop_iterations)},
      {"stop_gap", fieldAccess("stop_gap", &Parameters::stop_gap)},
      {"seed",
       {[](Parameters& p, const std::string& v) {
          char* end = nullptr;
          errno = 0;
          const unsigned long long s = std::strtoull(v.c_str(), &end, 10);
          // Digits only: strtoull skips leading spaces and negates "-1", so " -1" would wrap.
          if (v.empty() || !std::isdigit(static_cast<unsigned char>(v[0])) || *end != '\0' || errno == ERANGE)
            throw ParameterError("seed: '" + v + "' is not an integer in 0..18446744073709551615");
          p.seed = static_cast<std::uint64_t>(s);
        },
        [](const Parameters& p) { return ParameterValue{p.seed}; }}},
      {"threads", fieldAccess("threads", &Parameters::threads)},
      {"turn_cost", fieldAccess("turn_cost", &Parameters::turn_cost)},
      {"turn_cost_unit", wordAccess("turn_cost_unit", &Parameters::turn_cost_unit,
                                    {TurnCostUnit::kFreeCell, TurnCostUnit::kRouteCell})},
  };
  return table;
}

}  // namespace detail

inline std::vector<std::string> parameterNames() {
  std::vector<std::string> names;
  for (const auto& entry : detail::parameterTable()) names.push_back(entry.first);
  return names;
}

// Every parameter by name with its value (for reports: JSON, logs).
inline std::vector<std::pair<std::string, ParameterValue>> parameterValues(const Parameters& p) {
  std::vector<std::pair<std::string, ParameterValue>> values;
  for (const auto& [name, access] : detail::parameterTable()) values.emplace_back(name, access.get(p));
  return values;
}

// Sets one parameter from its text form. Throws ParameterError for an unknown
// key or a value of the wrong type; range checks are validate()'s job.
inline void setParameter(Parameters& p, const std::string& key, const std::string& value) {
  const auto& table = detail::parameterTable();
  const auto it = table.find(key);
  if (it == table.end()) {
    std::string known;
    for (const auto& entry : table) known += (known.empty() ? "" : ", ") + entry.first;
    throw ParameterError("unknown parameter '" + key + "' (known: " + known + ")");
  }
  it->second.set(p, value);
}

}  // namespace eaci
