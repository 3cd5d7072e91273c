// The paper's symbols for the parameters it names (m, Nc_max, α, ...) and the reports' prose
// of parameter values under them, read from a Parameters through the library's one table.
#pragma once

#include <string>
#include <vector>

#include "eaci/planner/parameters.hpp"

namespace eaci_bench {

// "alpha" -> "α", "ants" -> "m"; a name the paper has no symbol for stays as it is.
std::string paperSymbol(const std::string& name);

// "m = 50, Nc_max = 100, α = 1.1": the parameters `names` (eaci::parameterNames()) of `p`, in
// that order. Throws std::invalid_argument for an unknown name.
std::string symbolValues(const eaci::Parameters& p, const std::vector<std::string>& names,
                         const std::string& equals = " = ", const std::string& separator = ", ");

}  // namespace eaci_bench
