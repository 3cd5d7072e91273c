// Progress on stderr: a line per finished stage, "<command> | <stage> | run n/n | 12.3 s".
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace eaci_bench {

class Progress {
 public:
  explicit Progress(std::string command) : command_(std::move(command)), start_(std::chrono::steady_clock::now()) {}

  void show(const std::string& stage, int k, int n) const {
    if (k == n) std::fprintf(stderr, "%s | %s | run %d/%d | %.1f s\n", command_.c_str(), stage.c_str(), k, n, seconds());
  }
  void note(const std::string& line) const { std::fprintf(stderr, "%s: %s\n", command_.c_str(), line.c_str()); }
  void finish() const { std::fprintf(stderr, "%s: done in %.1f s\n", command_.c_str(), seconds()); }

 private:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

  std::string command_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace eaci_bench
