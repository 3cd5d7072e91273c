// Numbers in the tools' JSON reports: JSON has no infinity or NaN, so a non-finite number
// is written as null.
#pragma once

#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

namespace eaci::report {

inline nlohmann::json finiteOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

inline nlohmann::json finiteOrNull(const std::vector<double>& values) {
  nlohmann::json out = nlohmann::json::array();
  for (double v : values) out.push_back(finiteOrNull(v));
  return out;
}

}  // namespace eaci::report
