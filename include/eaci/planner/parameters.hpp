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
#include <utility>
#include <variant>
#include <vector>

#include "eaci/aco/colony_parameters.hpp"
#include "eaci/planner/parameter_text.hpp"

namespace eaci {

// The planner's configuration: the colony's settings, and the cost model, move rule and
// smoothing of every planner (A* included).
struct Parameters : ColonyParameters {
  bool allow_corner_cutting = false;  // diagonal between two corner-touching obstacles
  // The cost model of every planner (global_planner's): a move into a cell of cost c costs
  // step_length x (neutral_cost + cost_factor x c) / neutral_cost, and a route's cost, L_k, is
  // the sum. On a costmap, cells at or above lethal_cost are obstacles and the others have
  // cost c = their value; unknown cells are free (cost 0) only with allow_unknown. Map files
  // and OccupancyGrids have free cells of cost 0: a route's cost is its length there.
  double neutral_cost = 50.0;
  double cost_factor = 3.0;
  int lethal_cost = 253;      // costmap_2d INSCRIBED_INFLATED_OBSTACLE
  bool allow_unknown = false; // the ROS layer defaults to true, as navfn and global_planner do
  // After the search, shortcut the 8-connected route by line of sight (path/smoothing.hpp):
  // never through an obstacle, never costlier. Off for the paper's benchmarks; the ROS layer
  // turns it on.
  bool smooth_path = false;
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
  else if (p.threads < 0 || p.threads > 1024) e << "threads must be in 0..1024, 0 = all cores (got " << p.threads << ")";
  return e.str();
}

inline void validate(const Parameters& p) {
  const std::string error = validationError(p);
  if (!error.empty()) throw ParameterError(error);
}


namespace detail {

using Setter = std::function<void(Parameters&, const std::string&)>;

}  // namespace detail

// A parameter's value as it is: whole number, real number, boolean or word.
using ParameterValue = std::variant<std::int64_t, std::uint64_t, double, bool, std::string>;

namespace detail {

using Getter = std::function<ParameterValue(const Parameters&)>;

struct ParameterAccess {
  Setter set;
  Getter get;
};

// The one table of parameter names: CLI --set, --params files, ROS and the JSON output use it.
inline const std::map<std::string, ParameterAccess>& parameterTable() {
  static const std::map<std::string, ParameterAccess> table = {
      {"ants", {[](Parameters& p, const std::string& v) { p.ants = parseInt("ants", v); },
                [](const Parameters& p) { return ParameterValue{std::int64_t{p.ants}}; }}},
      {"max_iterations", {[](Parameters& p, const std::string& v) { p.max_iterations = parseInt("max_iterations", v); },
                          [](const Parameters& p) { return ParameterValue{std::int64_t{p.max_iterations}}; }}},
      {"alpha", {[](Parameters& p, const std::string& v) { p.alpha = parseDouble("alpha", v); },
                 [](const Parameters& p) { return ParameterValue{p.alpha}; }}},
      {"beta", {[](Parameters& p, const std::string& v) { p.beta = parseDouble("beta", v); },
                [](const Parameters& p) { return ParameterValue{p.beta}; }}},
      {"q", {[](Parameters& p, const std::string& v) { p.q = parseDouble("q", v); },
             [](const Parameters& p) { return ParameterValue{p.q}; }}},
      {"kappa", {[](Parameters& p, const std::string& v) { p.kappa = parseDouble("kappa", v); },
                 [](const Parameters& p) { return ParameterValue{p.kappa}; }}},
      {"islands", {[](Parameters& p, const std::string& v) { p.islands = parseInt("islands", v); },
                   [](const Parameters& p) { return ParameterValue{std::int64_t{p.islands}}; }}},
      {"lambda", {[](Parameters& p, const std::string& v) { p.lambda = parseDouble("lambda", v); },
                  [](const Parameters& p) { return ParameterValue{p.lambda}; }}},
      {"epsilon", {[](Parameters& p, const std::string& v) { p.epsilon = parseDouble("epsilon", v); },
                   [](const Parameters& p) { return ParameterValue{p.epsilon}; }}},
      {"aco_rho", {[](Parameters& p, const std::string& v) { p.aco_rho = parseDouble("aco_rho", v); },
                   [](const Parameters& p) { return ParameterValue{p.aco_rho}; }}},
      {"aco_tau0", {[](Parameters& p, const std::string& v) { p.aco_tau0 = parseDouble("aco_tau0", v); },
                    [](const Parameters& p) { return ParameterValue{p.aco_tau0}; }}},
      {"allow_corner_cutting",
       {[](Parameters& p, const std::string& v) { p.allow_corner_cutting = parseBool("allow_corner_cutting", v); },
        [](const Parameters& p) { return ParameterValue{p.allow_corner_cutting}; }}},
      {"neutral_cost", {[](Parameters& p, const std::string& v) { p.neutral_cost = parseDouble("neutral_cost", v); },
                        [](const Parameters& p) { return ParameterValue{p.neutral_cost}; }}},
      {"cost_factor", {[](Parameters& p, const std::string& v) { p.cost_factor = parseDouble("cost_factor", v); },
                       [](const Parameters& p) { return ParameterValue{p.cost_factor}; }}},
      {"lethal_cost", {[](Parameters& p, const std::string& v) { p.lethal_cost = parseInt("lethal_cost", v); },
                       [](const Parameters& p) { return ParameterValue{std::int64_t{p.lethal_cost}}; }}},
      {"smooth_path", {[](Parameters& p, const std::string& v) { p.smooth_path = parseBool("smooth_path", v); },
                       [](const Parameters& p) { return ParameterValue{p.smooth_path}; }}},
      {"allow_unknown",
       {[](Parameters& p, const std::string& v) { p.allow_unknown = parseBool("allow_unknown", v); },
        [](const Parameters& p) { return ParameterValue{p.allow_unknown}; }}},
      {"island_strategy",
       {[](Parameters& p, const std::string& v) {
          if (v == "geodesic") p.island_strategy = IslandStrategy::kGeodesic;
          else if (v == "paper") p.island_strategy = IslandStrategy::kPaper;
          else throw ParameterError("island_strategy: '" + v + "' is not one of: geodesic, paper");
        },
        [](const Parameters& p) { return ParameterValue{std::string(toString(p.island_strategy))}; }}},
      {"island_spacing_max",
       {[](Parameters& p, const std::string& v) { p.island_spacing_max = parseDouble("island_spacing_max", v); },
        [](const Parameters& p) { return ParameterValue{p.island_spacing_max}; }}},
      {"region_margin", {[](Parameters& p, const std::string& v) { p.region_margin = parseInt("region_margin", v); },
                         [](const Parameters& p) { return ParameterValue{std::int64_t{p.region_margin}}; }}},
      {"early_stop_iterations",
       {[](Parameters& p, const std::string& v) { p.early_stop_iterations = parseInt("early_stop_iterations", v); },
        [](const Parameters& p) { return ParameterValue{std::int64_t{p.early_stop_iterations}}; }}},
      {"stop_gap", {[](Parameters& p, const std::string& v) { p.stop_gap = parseDouble("stop_gap", v); },
                    [](const Parameters& p) { return ParameterValue{p.stop_gap}; }}},
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
      {"threads", {[](Parameters& p, const std::string& v) { p.threads = parseInt("threads", v); },
                   [](const Parameters& p) { return ParameterValue{std::int64_t{p.threads}}; }}},
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
