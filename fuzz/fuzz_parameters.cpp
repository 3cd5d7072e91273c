// setParameter + validationError, the path of the CLI's --set key=value (and of every other
// caller that sets parameters by name). Each input line is one assignment, split at its first
// '=' (a line without one is a key with an empty value), applied in order; then the result is
// validated. setParameter either sets the value or throws ParameterError; a value with a minus
// sign never sets a positive whole number; validate() throws exactly when validationError()
// reports something; and every value that was set reads back (parameterValues) as text that
// setParameter turns into the same value.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <variant>

#include "eaci/planner/parameters.hpp"
#include "fuzz_check.hpp"

namespace {

std::string toText(const eaci::ParameterValue& value) {
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const auto* u = std::get_if<std::uint64_t>(&value)) return std::to_string(*u);
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", std::get<double>(value));
  return text;
}

bool sameValue(const eaci::ParameterValue& a, const eaci::ParameterValue& b) {
  if (a.index() != b.index()) return false;
  const auto* x = std::get_if<double>(&a);
  const auto* y = std::get_if<double>(&b);
  if (x != nullptr && y != nullptr) return (std::isnan(*x) && std::isnan(*y)) || *x == *y;
  return a == b;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input = eaci::fuzz::asString(data, size);
  eaci::Parameters p;
  std::size_t begin = 0;
  while (begin <= input.size()) {
    std::size_t end = input.find('\n', begin);
    if (end == std::string::npos) end = input.size();
    const std::string line = input.substr(begin, end - begin);
    begin = end + 1;
    const std::size_t eq = line.find('=');
    const std::string key = line.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : line.substr(eq + 1);
    try {
      eaci::setParameter(p, key, value);
    } catch (const eaci::ParameterError& error) {
      FUZZ_CHECK(std::string(error.what()).size() > 0);
      continue;
    }
    // A minus sign never yields a positive whole number (strtoull negates "-1" to 2^64 - 1).
    const eaci::ParameterValue set = eaci::detail::parameterTable().at(key).get(p);
    const std::size_t sign = value.find_first_not_of(" \t\n\v\f\r");
    if (sign != std::string::npos && value[sign] == '-') {
      FUZZ_CHECK(!std::holds_alternative<std::uint64_t>(set));
      if (const auto* i = std::get_if<std::int64_t>(&set)) FUZZ_CHECK(*i <= 0);
    }
  }

  const std::string error = eaci::validationError(p);
  bool threw = false;
  try {
    eaci::validate(p);
  } catch (const eaci::ParameterError& e) {
    threw = true;
    FUZZ_CHECK(error == e.what());
  }
  FUZZ_CHECK(threw == !error.empty());

  // Every value reads back as text that sets the same value.
  eaci::Parameters copy;
  for (const auto& [name, value] : eaci::parameterValues(p)) {
    const std::string text = toText(value);
    try {
      eaci::setParameter(copy, name, text);
    } catch (const eaci::ParameterError& e) {
      std::fprintf(stderr, "cannot set %s back from '%s': %s\n", name.c_str(), text.c_str(), e.what());
      FUZZ_CHECK(false);
    }
  }
  const auto values = eaci::parameterValues(p);
  const auto copied = eaci::parameterValues(copy);
  FUZZ_CHECK(values.size() == copied.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!sameValue(values[i].second, copied[i].second)) {
      std::fprintf(stderr, "%s does not read back the same from '%s'\n", values[i].first.c_str(),
                   toText(values[i].second).c_str());
      FUZZ_CHECK(false);
    }
  }
  FUZZ_CHECK(eaci::validationError(copy) == error);
  return 0;
}
