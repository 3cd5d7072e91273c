#include "progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <sstream>

namespace eaci_bench {

Progress::Progress(std::string command)
    : command_(std::move(command)), terminal_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}

double Progress::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::clearLine() {
  if (terminal_ && line_open_) std::cerr << "\r\033[K";
  line_open_ = false;
}

void Progress::show(const std::string& stage, int k, int n) {
  std::ostringstream line;
  line.setf(std::ios::fixed);
  line.precision(1);
  line << command_ << " | " << stage << " | run " << k << "/" << n << " | " << elapsedSeconds() << " s";
  if (terminal_) {
    clearLine();
    std::cerr << line.str() << std::flush;
    line_open_ = true;
  } else if (k == n) {
    std::cerr << line.str() << std::endl;
  }
}

void Progress::note(const std::string& line) {
  clearLine();
  std::cerr << command_ << ": " << line << std::endl;
}

void Progress::finish() {
  clearLine();
  std::ostringstream line;
  line.setf(std::ios::fixed);
  line.precision(1);
  line << command_ << ": done in " << elapsedSeconds() << " s";
  std::cerr << line.str() << std::endl;
}

}  // namespace eaci_bench
