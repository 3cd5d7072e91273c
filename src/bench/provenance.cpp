#include "provenance.hpp"

#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

#include "source_state.hpp"  // generated at build time (cmake/source_state.cmake)

namespace eaci_bench {

namespace {

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

double memoryGb() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0.0;
  in >> key >> kb;
  return kb / (1024.0 * 1024.0);
}

double loadAverage() {
  std::ifstream in("/proc/loadavg");
  double one_minute = 0.0;
  in >> one_minute;
  return one_minute;
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return text;
}

std::string compilerName() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("g++ ") + __VERSION__;
#else
  return "unknown";
#endif
}

}  // namespace

Provenance collectProvenance(const std::string& command_line) {
  Provenance p;
  p.git_commit = source_state::kCommit;
  p.git_dirty = source_state::kDirty;
  p.modified_solver_sources = source_state::kModifiedSolverSources;
  p.compiler = compilerName();
#ifdef NDEBUG
  p.build_type = "optimised (NDEBUG)";
#else
  p.build_type = "assertions on (no NDEBUG)";
#endif
  p.cpu_model = cpuModel();
  p.hardware_threads = std::thread::hardware_concurrency();
  p.memory_gb = memoryGb();
  p.date_utc = utcNow();
  p.load_average_at_start = loadAverage();
  p.command_line = command_line;
  return p;
}

std::string provenanceMarkdown(const Provenance& p) {
  std::ostringstream s;
  s << "Source `" << p.git_commit << "`";
  if (!p.modified_solver_sources.empty()) {
    s << " with uncommitted changes to";
    for (const std::string& f : p.modified_solver_sources) s << " `" << f << "`";
  } else if (p.git_dirty) {
    s << " with uncommitted changes outside the solver sources";
  }
  s << "; " << p.compiler << ", " << p.build_type << "; " << p.cpu_model << ", " << p.hardware_threads
    << " hardware threads, " << static_cast<int>(p.memory_gb + 0.5) << " GB; " << p.date_utc
    << "; load average " << p.load_average_at_start << " when the run began.\n\n"
    << "Command: `" << p.command_line << "`\n";
  return s.str();
}

}  // namespace eaci_bench
