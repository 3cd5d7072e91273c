// Where numbers come from: the source commit eaci_bench was built from (and which solver files
// differed from it), the compiler, the machine.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace eaci_bench {

struct Provenance {
  // The source eaci_bench was built from (taken when it was built, not when it runs):
  std::string git_commit;                    // short hash of HEAD, "unknown" outside a checkout
  bool git_dirty = false;                    // anything uncommitted in the tree
  std::vector<std::string> modified_solver_sources; // files under include/ and src/io that differ from HEAD
  std::string compiler;
  std::string build_type;
  std::string cpu_model;
  unsigned hardware_threads = 0;
  double memory_gb = 0.0;
  std::string date_utc;
  double load_average_at_start = 0.0;        // 1-minute load average when the run began
  std::string command_line;
};

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Provenance, git_commit, git_dirty, modified_solver_sources, compiler, build_type,
                                   cpu_model, hardware_threads, memory_gb, date_utc, load_average_at_start,
                                   command_line)

Provenance collectProvenance(const std::string& command_line);
// Two Markdown lines for the reports.
std::string provenanceMarkdown(const Provenance& p);

}  // namespace eaci_bench
