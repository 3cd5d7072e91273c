// Where numbers come from: the source commit (and which solver files differ from it),
// the compiler, the machine.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace eaci_bench {

struct Provenance {
  std::string git_commit;                    // short hash of HEAD, "unknown" outside a checkout
  std::vector<std::string> modified_solver_sources; // tracked files under include/ and src/io that differ from HEAD
  std::string compiler;
  std::string build_type;
  std::string cpu_model;
  unsigned hardware_threads = 0;
  double memory_gb = 0.0;
  std::string date_utc;
  double load_average_at_start = 0.0;        // 1-minute load average when the run began
  std::string command_line;
};

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Provenance, git_commit, modified_solver_sources, compiler, build_type, cpu_model,
                                   hardware_threads, memory_gb, date_utc, load_average_at_start, command_line)

Provenance collectProvenance(const std::string& command_line);
// Two Markdown lines for the reports.
std::string provenanceMarkdown(const Provenance& p);

}  // namespace eaci_bench
