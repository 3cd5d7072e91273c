// Progress on stderr: one line that updates in place on a terminal, one line per finished
// stage when stderr is a file or a pipe.
#pragma once

#include <chrono>
#include <string>

namespace eaci_bench {

class Progress {
 public:
  explicit Progress(std::string command);

  // "<command> | <stage> | run k/n | 12.3 s"
  void show(const std::string& stage, int k, int n);
  // A line of its own (notes, warnings), above the progress line.
  void note(const std::string& line);
  // Ends the progress line.
  void finish();

  double elapsedSeconds() const;

 private:
  void clearLine();

  std::string command_;
  bool terminal_;
  bool line_open_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace eaci_bench
