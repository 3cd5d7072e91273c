#include "replay_writer.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

namespace eaci_service {

namespace fs = std::filesystem;

ReplayWriter::ReplayWriter(std::string directory, int keep, std::function<void(const std::string&, bool)> report)
    : directory_(std::move(directory)), keep_(std::max(0, keep)), report_(std::move(report)) {}

ReplayWriter::~ReplayWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

bool ReplayWriter::submit(ReplayJob job) noexcept {
  try {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return false;
    waiting_ = std::move(job);
    if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
  } catch (...) {  // no memory for the job, or no thread: the plan's failure is logged anyway
    std::lock_guard<std::mutex> lock(mutex_);
    waiting_.reset();
    return false;
  }
  wake_.notify_one();
  return true;
}

void ReplayWriter::run() {
  for (;;) {
    std::optional<ReplayJob> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || waiting_.has_value(); });
      if (!waiting_) return;  // stopping, nothing left to write
      job.swap(waiting_);
    }
    try {
      const ReplayFiles files = writeNow(*job);
      if (report_) report_("saved the costmap as " + files.map_yaml + (files.command.empty() ? "" : "; replay: " + files.command), true);
    } catch (const std::exception& e) {
      try {
        if (report_) report_(std::string("cannot save the costmap: ") + e.what(), false);
      } catch (...) {
      }
    } catch (...) {
    }
  }
}

ReplayFiles ReplayWriter::writeNow(const ReplayJob& job) {
  const ReplayFiles files = saveCostmapForReplay(directory_, timestampedName(job.prefix), job.costmap, job.params,
                                                 job.algorithm, job.request, job.notes);
  prune(job.prefix);
  return files;
}

// The replays of one prefix are <prefix>_<timestamp>.{yaml,pgm,params.yaml}: the timestamps
// sort as text, so the newest `keep_` are the last.
void ReplayWriter::prune(const std::string& prefix) const {
  if (keep_ == 0) return;
  std::error_code error;
  std::vector<std::string> stamps;
  const std::string start = prefix + "_";
  for (fs::directory_iterator it(directory_, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    const std::string suffix = ".params.yaml";
    if (name.size() > start.size() + suffix.size() && name.compare(0, start.size(), start) == 0 &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      stamps.push_back(name.substr(0, name.size() - suffix.size()));
  }
  if (stamps.size() <= static_cast<std::size_t>(keep_)) return;
  std::sort(stamps.begin(), stamps.end());
  for (std::size_t i = 0; i + keep_ < stamps.size(); ++i)
    for (const char* ending : {".yaml", ".pgm", ".params.yaml"})
      fs::remove(fs::path(directory_) / (stamps[i] + ending), error);
}

}  // namespace eaci_service
