// A number in a message or report: the one number-to-text helper of the project (the core's
// error sentences, the planning service, the adapters, the tools, the benchmarks). A utility
// every layer may use (scripts/check_layers.sh).
#pragma once

#include <cstdio>
#include <string>

namespace eaci {

// `value` with at most `max_decimals` decimals and no trailing zeros: "0.05", "20", "33.3137".
inline std::string formatNumber(double value, int max_decimals = 4) {
  char buffer[400];  // %f of the largest double: 309 digits, the sign, the point, the decimals
  const int decimals = max_decimals < 0 ? 0 : max_decimals > 60 ? 60 : max_decimals;
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string text = buffer;
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

}  // namespace eaci
