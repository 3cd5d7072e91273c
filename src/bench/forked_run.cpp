#include "forked_run.hpp"

#include <malloc.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>

namespace eaci_bench {

namespace {

constexpr double kKibPerMib = 1024.0;

double residentMib() {
  std::ifstream statm("/proc/self/statm");
  long pages_total = 0, pages_resident = 0;
  statm >> pages_total >> pages_resident;
  return static_cast<double>(pages_resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

bool writeAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string readAll(int fd) {
  std::string bytes;
  char buffer[65536];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  return bytes;
}

// In the child: first line = resident MiB at start, then the work's output.
[[noreturn]] void childMain(int fd, const std::function<std::string()>& work) {
  int status = 0;
  try {
    const std::string start = std::to_string(residentMib()) + "\n";
    const std::string output = work();
    if (!writeAll(fd, start + output)) status = 2;
  } catch (const std::exception& e) {
    writeAll(fd, std::string("0\nerror: ") + e.what());
    status = 1;
  }
  close(fd);
  _exit(status);  // no atexit handlers, no flushing of the parent's buffers
}

}  // namespace

ForkedResult runForked(const std::function<std::string()>& work) {
  ForkedResult result;
  int fds[2];
  if (pipe(fds) != 0) {
    result.error = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  malloc_trim(0);  // hand freed heap back to the system: the child starts from what is really in use
  const pid_t pid = fork();
  if (pid < 0) {
    result.error = std::string("fork: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return result;
  }
  if (pid == 0) {
    close(fds[0]);
    childMain(fds[1], work);
  }
  close(fds[1]);
  const std::string bytes = readAll(fds[0]);  // before waiting: a full pipe would block the child
  close(fds[0]);
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  const std::size_t newline = bytes.find('\n');
  result.start_rss_mb = newline == std::string::npos ? 0.0 : std::atof(bytes.substr(0, newline).c_str());
  result.output = newline == std::string::npos ? std::string() : bytes.substr(newline + 1);
  result.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / kKibPerMib;
  result.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!result.ok)
    result.error = WIFSIGNALED(status) ? "child killed by signal " + std::to_string(WTERMSIG(status))
                                       : "child failed: " + result.output;
  return result;
}

}  // namespace eaci_bench
