// Numbers in the tools' JSON reports: JSON has no infinity or NaN, so a non-finite number
// is written as null (as nlohmann::json's dump() also writes one), and read back as +infinity.
#pragma once

#include <cmath>
#include <limits>
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

// Every null in `j` becomes +infinity, so that a report read back gives its numbers again
// (get<double>() refuses null).
inline void nullsToInfinity(nlohmann::json& j) {
  if (j.is_null()) j = std::numeric_limits<double>::infinity();
  if (!j.is_structured()) return;  // a number, string or bool iterates over itself
  for (nlohmann::json& item : j) nullsToInfinity(item);
}

}  // namespace eaci::report
