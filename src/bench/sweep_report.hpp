// Writers for `eaci_bench sweep`: JSON, CSV (one row per sweep point), Markdown.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "provenance.hpp"
#include "sweeps.hpp"

namespace eaci_bench {

nlohmann::json sweepJson(const std::vector<SweepPoint>& eaci, const std::vector<RhoPoint>& rho,
                         const SweepOptions& options, const Provenance& provenance);
std::string sweepCsv(const std::vector<SweepPoint>& eaci, const std::vector<RhoPoint>& rho);
std::string sweepMarkdown(const std::vector<SweepPoint>& eaci, const std::vector<RhoPoint>& rho,
                          const SweepOptions& options, const Provenance& provenance);

}  // namespace eaci_bench
