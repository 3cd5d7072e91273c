// Where numbers come from: the source commit (and which solver files differ from it),
// the compiler, the machine.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace eaci_bench {

struct Provenance {
  std::string git_commit;                    // short hash of HEAD, "unknown" outside a checkout
  std::vector<std::string> modified_sources; // tracked files under include/ and src/ that differ from HEAD
  std::string compiler;
  std::string build_type;
  std::string cpu_model;
  unsigned hardware_threads = 0;
  double memory_gb = 0.0;
  std::string date_utc;
  double load_average = 0.0;                 // 1-minute load average when the run began
  std::string command_line;
};

Provenance collectProvenance(const std::string& command_line);
nlohmann::json toJson(const Provenance& p);
// Two Markdown lines for the reports.
std::string provenanceMarkdown(const Provenance& p);

}  // namespace eaci_bench
