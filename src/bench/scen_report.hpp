// The report of `eaci_bench scen`: JSON (options, parameters, provenance, summary, every
// problem with its runs), CSV (one row per problem) and Markdown (summary and a table).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "provenance.hpp"
#include "scen.hpp"

namespace eaci_bench {

nlohmann::json scenJson(const ScenResult& result, const ScenOptions& options, const Provenance& provenance);
std::string scenCsv(const ScenResult& result);
std::string scenMarkdown(const ScenResult& result, const ScenOptions& options, const Provenance& provenance);
// "12 problems, 0 mismatches, EACI gap median 0.00 % worst 3.10 %, time EACI/A* median 41.2x"
std::string scenSummaryLine(const ScenSummary& s);

}  // namespace eaci_bench
