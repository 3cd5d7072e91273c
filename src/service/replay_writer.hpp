// Writes replay files (costmap_replay.hpp) on a thread of its own, so that a planner thread
// that saves the costmap of a failed plan (~save_costmap_on_failure) never waits for a disk,
// and keeps only the newest files of each kind: at 1 Hz replanning towards an unreachable goal
// that would otherwise be a new map every second.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "costmap_replay.hpp"

namespace eaci_service {

struct ReplayJob {
  std::string prefix;  // the files' name starts with it (timestampedName)
  CostmapSnapshot costmap;
  eaci::Parameters params;
  eaci::Algorithm algorithm = eaci::Algorithm::kEaci;
  std::optional<PlanRecord> request;
  std::vector<std::string> notes;
};

class ReplayWriter {
 public:
  // Files go to `directory`; of the replays whose name starts with a job's prefix the newest
  // `keep` are kept (0 = all). `report(line, ok)` hears of every save (its paths and replay
  // command) or failure, on the writer's thread.
  ReplayWriter(std::string directory, int keep, std::function<void(const std::string&, bool)> report);
  ~ReplayWriter();  // writes the job waiting, if any, then joins
  ReplayWriter(const ReplayWriter&) = delete;
  ReplayWriter& operator=(const ReplayWriter&) = delete;

  // Hands a job to the writer's thread and returns at once. A job still waiting is replaced
  // (only the newest failure is worth a file); false when the thread could not be started.
  bool submit(ReplayJob job) noexcept;

  // Writes `job` on the calling thread (the ~save_costmap service) and prunes the old files.
  // Throws what saveCostmapForReplay throws.
  ReplayFiles writeNow(const ReplayJob& job);

 private:
  void run();
  void prune(const std::string& prefix) const;

  const std::string directory_;
  const int keep_;
  const std::function<void(const std::string&, bool)> report_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<ReplayJob> waiting_;  // under mutex_
  bool stopping_ = false;             // under mutex_
  std::thread thread_;                // started with the first job
};

}  // namespace eaci_service
