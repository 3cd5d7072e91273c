// Parameter values from text (CLI --set, parameter files, ROS strings, the service's options):
// the whole text must be the value, or ParameterError names the key.
#pragma once

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

namespace eaci {

class ParameterError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A real number (no subnormals, nothing after it).
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

// A whole number in base 10.
inline long long parseInteger(const std::string& key, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(begin, &end, 10);
  if (text.empty() || end == begin || *end != '\0' || errno == ERANGE)
    throw ParameterError(key + ": '" + text + "' is not an integer");
  return v;
}

// A whole number that fits an int.
inline int parseInt(const std::string& key, const std::string& text) {
  const long long v = parseInteger(key, text);
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    throw ParameterError(key + ": " + text + " is out of range");
  return static_cast<int>(v);
}

// true/false, 1/0, yes/no, on/off, in any case.
inline bool parseBool(const std::string& key, const std::string& text) {
  std::string t = text;
  for (char& ch : t) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (t == "true" || t == "1" || t == "yes" || t == "on") return true;
  if (t == "false" || t == "0" || t == "no" || t == "off") return false;
  throw ParameterError(key + ": '" + text + "' is not a boolean (true/false)");
}

}  // namespace eaci
