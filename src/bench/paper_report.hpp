// Writers for `eaci_bench paper`: JSON (everything), CSV (one row per map x algorithm,
// and one per run), Markdown (our numbers beside the paper's).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "paper_tables.hpp"
#include "provenance.hpp"

namespace eaci_bench {

nlohmann::json paperJson(const std::vector<MapResult>& results, const PaperOptions& options,
                         const Provenance& provenance);
std::string paperSummaryCsv(const std::vector<MapResult>& results);
std::string paperRunsCsv(const std::vector<MapResult>& results);
std::string paperMarkdown(const std::vector<MapResult>& results, const PaperOptions& options,
                          const Provenance& provenance);

}  // namespace eaci_bench
