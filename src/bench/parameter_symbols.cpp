#include "parameter_symbols.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "eaci/io/text.hpp"

namespace eaci_bench {

namespace {

const std::map<std::string, std::string>& paperSymbols() {
  static const std::map<std::string, std::string> symbols = {
      {"ants", "m"},      {"max_iterations", "Nc_max"}, {"alpha", "α"},   {"beta", "β"},
      {"q", "Q"},         {"kappa", "κ"},               {"islands", "N"}, {"lambda", "λ"},
      {"epsilon", "ε"},   {"aco_rho", "ρ"},             {"aco_tau0", "τ0"},
  };
  return symbols;
}

std::string valueText(const eaci::ParameterValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>) return eaci::formatNumber(v, 6);
        else if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::string>) return v;
        else return std::to_string(v);
      },
      value);
}

}  // namespace

std::string paperSymbol(const std::string& name) {
  const auto it = paperSymbols().find(name);
  return it == paperSymbols().end() ? name : it->second;
}

std::string symbolValues(const eaci::Parameters& p, const std::vector<std::string>& names, const std::string& equals,
                         const std::string& separator) {
  const auto values = eaci::parameterValues(p);
  std::string text;
  for (const std::string& name : names) {
    const auto it = std::find_if(values.begin(), values.end(), [&](const auto& entry) { return entry.first == name; });
    if (it == values.end()) throw std::invalid_argument("unknown parameter '" + name + "'");
    text += (text.empty() ? "" : separator) + paperSymbol(name) + equals + valueText(it->second);
  }
  return text;
}

}  // namespace eaci_bench
