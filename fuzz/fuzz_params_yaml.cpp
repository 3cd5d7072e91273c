// The CLI's --params FILE.yaml: a flat YAML mapping of parameter names to scalar values.
// eaci_plan reads it in applyParameterFile() inside src/tools/eaci_plan.cpp, which is not a
// library function; this target runs the same steps on the input text (YAML::Load instead of
// YAML::LoadFile, then the same checks in the same order, then validationError). Keep it in
// step with applyParameterFile. Every input must end in a clean error (YAML::Exception,
// ParameterError or one of the file-shape errors) or in a parameter set.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "eaci/aco/parameters.hpp"
#include "fuzz_check.hpp"

namespace {

// eaci_plan's InputError.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Mirror of applyParameterFile (src/tools/eaci_plan.cpp) from text instead of a file.
void applyParameterText(eaci::Parameters& p, const std::string& text) {
  const std::string where = "--params 'fuzz.yaml'";
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(where + " is not valid YAML: " + e.what());
  }
  if (!root.IsMap()) {
    const char* kind = root.IsNull() ? "an empty document" : root.IsSequence() ? "a list" : "a single value";
    throw InputError(where + ": expected a mapping of parameter names to values, got " + kind);
  }
  for (const auto& entry : root) {
    if (!entry.first.IsScalar()) throw InputError(where + ": parameter names must be plain words");
    const std::string key = entry.first.Scalar();
    if (entry.second.IsNull()) throw InputError(where + ": '" + key + "' has no value");
    if (!entry.second.IsScalar())
      throw InputError(where + ": '" + key + "' must be a single value, not a list or mapping (the file is flat)");
    try {
      eaci::setParameter(p, key, entry.second.Scalar());
    } catch (const eaci::ParameterError& e) {
      bool flag = false;
      if (!YAML::convert<bool>::decode(entry.second, flag)) throw InputError(where + ": " + e.what());
      try {
        eaci::setParameter(p, key, flag ? "true" : "false");
      } catch (const eaci::ParameterError&) {
        throw InputError(where + ": " + e.what());
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  eaci::Parameters p;
  try {
    applyParameterText(p, eaci::fuzz::asString(data, size));
  } catch (const InputError& error) {
    FUZZ_CHECK(std::string(error.what()).size() > 0);
    return 0;
  }
  // eaci_plan's main() reports any other YAML::Exception as a clean error too.
  catch (const YAML::Exception&) {
    return 0;
  }
  const std::string error = eaci::validationError(p);
  FUZZ_CHECK(error.find('\n') == std::string::npos);
  return 0;
}
