#include "eaci/planner/parameter_file.hpp"

#include <yaml-cpp/depthguard.h>  // YAML::DeepRecursion (yaml-cpp 0.7)
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <type_traits>
#include <variant>

#include "eaci/io/text.hpp"

namespace eaci {
namespace {

constexpr std::size_t kMaxParameterFileBytes = std::size_t{1} << 20;

[[noreturn]] void fail(const std::string& message) { throw ParameterFileError(message); }

YAML::Node parse(const std::string& text, const std::string& source) {
  try {
    return YAML::Load(text);
  } catch (const YAML::DeepRecursion&) {
    // yaml-cpp 0.7 reports its nesting limit as "error at line 1, column 1: bad file".
    fail(source + " is not valid YAML: it is nested more deeply than the YAML reader allows");
  } catch (const YAML::Exception& e) {
    fail(source + " is not valid YAML: " + e.what());
  }
}

void applyEntries(const YAML::Node& root, Parameters& p, const std::string& source) {
  if (!root.IsMap()) {
    const char* kind = root.IsNull() ? "an empty document" : root.IsSequence() ? "a list" : "a single value";
    fail(source + ": expected a mapping of parameter names to values, got " + kind);
  }
  for (const auto& entry : root) {
    if (!entry.first.IsScalar()) fail(source + ": parameter names must be plain words");
    const std::string key = entry.first.Scalar();
    if (entry.second.IsNull()) fail(source + ": '" + key + "' has no value");
    if (!entry.second.IsScalar())
      fail(source + ": '" + key + "' must be a single value, not a list or mapping (the file is flat)");
    try {
      setParameter(p, key, entry.second.Scalar());
    } catch (const ParameterError& e) {
      // YAML spells booleans in more ways (True, YES, ...) than setParameter accepts.
      bool flag = false;
      if (!YAML::convert<bool>::decode(entry.second, flag)) fail(source + ": " + e.what());
      try {
        setParameter(p, key, flag ? "true" : "false");
      } catch (const ParameterError&) {
        fail(source + ": " + e.what());
      }
    }
  }
}

}  // namespace

void applyParameterYaml(const std::string& text, Parameters& params, const std::string& source) {
  const YAML::Node root = parse(text, source);
  try {
    applyEntries(root, params, source);
  } catch (const YAML::Exception& e) {  // not expected once parsed; kept a ParameterFileError
    fail(source + ": " + e.what());
  }
}

void applyParameterFile(const std::string& path, Parameters& params, const std::string& source) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(source + ": cannot open the file");
  std::string text;
  char buffer[4096];
  while (in.read(buffer, sizeof(buffer)) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxParameterFileBytes) fail(source + ": larger than 1 MiB, not a parameter file");
  }
  if (in.bad()) fail(source + ": cannot read the file");
  applyParameterYaml(text, params, source);
}

std::string parameterYaml(const Parameters& params) {
  YAML::Emitter yaml;
  yaml << YAML::BeginMap;
  for (const auto& [name, value] : parameterValues(params)) {
    yaml << YAML::Key << name << YAML::Value;
    std::visit(
        [&yaml](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, double>) yaml << exactNumber(v);
          else if constexpr (std::is_same_v<T, bool>) yaml << (v ? "true" : "false");
          else yaml << v;
        },
        value);
  }
  yaml << YAML::EndMap;
  return std::string(yaml.c_str()) + "\n";
}

}  // namespace eaci
