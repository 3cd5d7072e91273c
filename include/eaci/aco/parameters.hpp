// All solver parameters in one place, with the paper's defaults (Section 5),
// validated in one place, and settable by name (CLI --set, --params YAML, ROS).
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

namespace eaci {

enum class IslandStrategy {
  kGeodesic,  // on a shortest route, r_s apart, legs guided by exact grid distance (beyond the paper)
  kPaper,     // Eq. 13-15 on the auxiliary map, as the paper defines them
};

struct Parameters {
  int ants = 50;                 // m
  int max_iterations = 100;      // Nc_max
  double alpha = 1.1;            // pheromone weight (Eq. 8)
  double beta = 7.0;             // heuristic weight (Eq. 8)
  double q = 100.0;              // pheromone deposit constant Q (Eq. 11, 24)
  double kappa = 0.9;            // adaptive evaporation coefficient (Eq. 25)
  int islands = 9;               // N, islands including S and E (Eq. 13)
  double lambda = 3.0;           // pheromone expansion coefficient (Eq. 21)
  double epsilon = 0.5;          // angle coefficient of the turning cost (Eq. 17)
  // Classic ACO evaporation rate (Eq. 10) and uniform initial pheromone; the paper gives
  // neither. tau0 = 800 with Q = 100 is the common MATLAB ACO code's tau0 = 8 with Q = 1 and,
  // with rho = 0.1, puts the baseline's iterations and lost ants within a factor 2 of the
  // paper's ACO row on all four maps (docs/benchmarks.md, `eaci_bench sweep`).
  double aco_rho = 0.1;
  double aco_tau0 = 800.0;
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
  IslandStrategy island_strategy = IslandStrategy::kGeodesic;
  double island_spacing_max = 2.0;   // geodesic islands: at most this many cells apart (0 = r_s only)
  // Geodesic islands: the ants walk on the cells at most this many moves from the cheapest
  // route (ColonyRegion), so memory and set-up follow the route, not the map; 0 = the whole
  // map. The paper's islands and classic ACO always use the whole map.
  int region_margin = 12;
  int early_stop_iterations = 0;  // stop after this many iterations without improvement; 0 = off
  // With early stopping on (early_stop_iterations > 0), geodesic EACI also stops as soon as its
  // best route costs at most (1 + stop_gap) x the cheapest route's cost, which its A* search
  // knows before the ants start: 0 = once a route is as cheap (no later iteration could beat
  // it); 0.01 = within 1 %. The paper's islands and classic ACO know no such cost.
  double stop_gap = 0.0;
  std::uint64_t seed = 1;
  int threads = 1;  // ants of one iteration spread over this many threads; 0 = all cores
};

class ParameterError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
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


inline const char* toString(IslandStrategy s) {
  switch (s) {
    case IslandStrategy::kGeodesic: return "geodesic";
    case IslandStrategy::kPaper: return "paper";
  }
  return "?";
}

namespace detail {

inline double parseDouble(const std::string& key, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  // Subnormal values are refused however they are spelt: strtod flags "1e-320" with ERANGE but
  // not an exact "0x4p-1074", which then could not be written back in decimal (fuzz_parameters).
  const bool subnormal = v != 0 && std::fabs(v) < std::numeric_limits<double>::min();
  if (text.empty() || end == begin || *end != '\0' || errno == ERANGE || subnormal)
    throw ParameterError(key + ": '" + text + "' is not a number");
  return v;
}

inline long long parseInteger(const std::string& key, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(begin, &end, 10);
  if (text.empty() || end == begin || *end != '\0' || errno == ERANGE)
    throw ParameterError(key + ": '" + text + "' is not an integer");
  return v;
}

inline int parseInt(const std::string& key, const std::string& text) {
  const long long v = parseInteger(key, text);
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    throw ParameterError(key + ": " + text + " is out of range");
  return static_cast<int>(v);
}

inline bool parseBool(const std::string& key, const std::string& text) {
  std::string t = text;
  for (char& ch : t) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (t == "true" || t == "1" || t == "yes" || t == "on") return true;
  if (t == "false" || t == "0" || t == "no" || t == "off") return false;
  throw ParameterError(key + ": '" + text + "' is not a boolean (true/false)");
}

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
