// Parameter files: a flat YAML mapping of parameter names to scalar values (the CLI's
// `--params FILE.yaml`), applied on top of a Parameters value.
#pragma once

#include <stdexcept>
#include <string>

#include "eaci/planner/parameters.hpp"

namespace eaci {

// What is wrong with a parameter file: one line that starts with the file's name (the
// `source` given below) and names the key when one is at fault.
class ParameterFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Sets every `name: value` of the YAML mapping `text` with setParameter(), in file order, on
// top of `params` (YAML's spellings of booleans, such as True or yes, are accepted too). Does
// not validate the result as a whole (call validate()). Throws ParameterFileError, beginning
// with `source`, when the text is not YAML, not a mapping, or a key is unknown, has no value,
// a list or mapping as value, or a value setParameter() refuses; `params` may then be partly set.
void applyParameterYaml(const std::string& text, Parameters& params, const std::string& source = "parameter YAML");

// The same read from the file at `path`: "<source>: cannot open the file" when it cannot be
// read, and files over 1 MiB are refused.
void applyParameterFile(const std::string& path, Parameters& params, const std::string& source);

// Every parameter of `params` as a parameter file: one `name: value` line each, in
// parameterNames() order, numbers written exactly, so that applyParameterYaml() reads back
// the same values (the CLI's --params FILE replays a planner's settings).
std::string parameterYaml(const Parameters& params);

}  // namespace eaci
