// Small text parsers for eaci_plan's arguments: "R,C", "X,Y", serial numbers, "key=value".
// Each throws std::invalid_argument with a one-line reason that names the option.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "eaci/grid/cell.hpp"

namespace eaci::cli {

inline std::string trim(const std::string& text) {
  const char* space = " \t\r\n";
  const auto first = text.find_first_not_of(space);
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(space);
  return text.substr(first, last - first + 1);
}

// Splits "a,b" at its only comma; throws unless there are exactly two non-empty parts.
inline std::pair<std::string, std::string> splitPair(const std::string& text, const std::string& option,
                                                     const char* expected) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    throw std::invalid_argument(option + ": '" + text + "' is not " + expected);
  std::pair<std::string, std::string> parts{trim(text.substr(0, comma)), trim(text.substr(comma + 1))};
  if (parts.first.empty() || parts.second.empty())
    throw std::invalid_argument(option + ": '" + text + "' is not " + expected);
  return parts;
}

inline long long parseWholeNumber(const std::string& part, const std::string& option, const std::string& text,
                                  const char* expected) {
  const char* begin = part.c_str();
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(begin, &end, 10);
  if (part.empty() || end == begin || *end != '\0')
    throw std::invalid_argument(option + ": '" + text + "' is not " + expected);
  if (errno == ERANGE) throw std::invalid_argument(option + ": '" + text + "' is out of range");
  return v;
}

inline double parseReal(const std::string& part, const std::string& option, const std::string& text,
                        const char* expected) {
  const char* begin = part.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (part.empty() || end == begin || *end != '\0')
    throw std::invalid_argument(option + ": '" + text + "' is not " + expected);
  if (errno == ERANGE || !std::isfinite(v))
    throw std::invalid_argument(option + ": '" + text + "' is not a finite coordinate");
  return v;
}

// "R,C": 0-based row (0 = top) and column. Whether the cell lies on the map is checked later.
inline Cell parseRowCol(const std::string& text, const std::string& option) {
  static const char* kExpected = "ROW,COL (two integers, e.g. 0,5)";
  const auto parts = splitPair(text, option, kExpected);
  const long long row = parseWholeNumber(parts.first, option, text, kExpected);
  const long long col = parseWholeNumber(parts.second, option, text, kExpected);
  constexpr long long kMin = std::numeric_limits<int>::min(), kMax = std::numeric_limits<int>::max();
  if (row < kMin || row > kMax || col < kMin || col > kMax)
    throw std::invalid_argument(option + ": '" + text + "' is out of range");
  return Cell{static_cast<int>(row), static_cast<int>(col)};
}

// "X,Y": map-frame metres, both finite.
inline std::pair<double, double> parseXY(const std::string& text, const std::string& option) {
  static const char* kExpected = "X,Y (two numbers in metres, e.g. 0.4,1.5)";
  const auto parts = splitPair(text, option, kExpected);
  return {parseReal(parts.first, option, text, kExpected), parseReal(parts.second, option, text, kExpected)};
}

// The paper's 1-based serial number; the range 1..W*H is checked by the caller.
inline std::int64_t parseSerial(const std::string& text, const std::string& option) {
  return parseWholeNumber(trim(text), option, text, "a cell serial number (an integer >= 1)");
}

// A distance or factor: one finite number >= 0 (metres for distances).
inline double parseNonNegative(const std::string& text, const std::string& option) {
  static const char* kExpected = "a number >= 0";
  const std::string part = trim(text);
  const char* begin = part.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (part.empty() || end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(v) || v < 0)
    throw std::invalid_argument(option + ": '" + text + "' is not " + kExpected);
  return v;
}

// "key=value" (split at the first '='); the key must not be empty.
inline std::pair<std::string, std::string> splitAssignment(const std::string& text, const std::string& option) {
  const auto eq = text.find('=');
  if (eq == std::string::npos)
    throw std::invalid_argument(option + ": '" + text + "' is not key=value");
  std::pair<std::string, std::string> kv{trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
  if (kv.first.empty()) throw std::invalid_argument(option + ": '" + text + "' has no key before '='");
  return kv;
}

}  // namespace eaci::cli
