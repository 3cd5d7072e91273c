// Every solver parameter by name and value (eaci::parameterValues, the library's one table)
// as a JSON object, for the tools' reports.
#pragma once

#include <type_traits>
#include <variant>

#include <nlohmann/json.hpp>

#include "common/json_number.hpp"
#include "eaci/planner/parameters.hpp"

namespace eaci::report {

inline nlohmann::json parametersToJson(const Parameters& parameters) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, value] : parameterValues(parameters)) {
    out[name] = std::visit(
        [](const auto& v) -> nlohmann::json {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, double>) return finiteOrNull(v);
          else return v;
        },
        value);
  }
  return out;
}

}  // namespace eaci::report
