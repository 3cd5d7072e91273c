// Runs a piece of work in a forked child process and reports the child's peak memory
// (ru_maxrss from wait4), so every plan's peak is measured on its own.
#pragma once

#include <functional>
#include <string>

namespace eaci_bench {

struct ForkedResult {
  bool ok = false;           // the child exited with status 0
  std::string output;        // what the work returned
  std::string error;         // why not ok
  double peak_rss_mb = 0.0;  // the child's peak resident set (MiB), including the pages it shares
                             // with the parent (the parent trims its heap before forking)
  double start_rss_mb = 0.0; // the child's resident set when the work began (MiB)
};

// `work` runs in the child; its return value travels back through a pipe. The parent must
// not have other threads running (fork copies only the calling thread).
ForkedResult runForked(const std::function<std::string()>& work);

}  // namespace eaci_bench
