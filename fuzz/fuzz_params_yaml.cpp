// The CLI's --params FILE.yaml: a flat YAML mapping of parameter names to scalar values, read
// by eaci::applyParameterYaml (src/planner/parameter_file.cpp), the function eaci_plan calls. Every
// input must end in a ParameterFileError of one line that names the source, or in a parameter
// set whose validation error (if any) is one line.
#include <cstdint>
#include <string>

#include "eaci/planner/parameters.hpp"
#include "eaci/planner/parameter_file.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  eaci::Parameters p;
  try {
    eaci::applyParameterYaml(eaci::fuzz::asString(data, size), p, "--params 'fuzz.yaml'");
  } catch (const eaci::ParameterFileError& error) {
    FUZZ_CHECK(std::string(error.what()).rfind("--params 'fuzz.yaml'", 0) == 0);
    return 0;
  }
  const std::string error = eaci::validationError(p);
  FUZZ_CHECK(error.find('\n') == std::string::npos);
  return 0;
}
