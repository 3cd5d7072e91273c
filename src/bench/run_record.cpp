#include "run_record.hpp"

#include "common/json_number.hpp"

namespace eaci_bench {

nlohmann::json toJson(const RunRecord& run, bool with_curves, bool with_path) {
  nlohmann::json j = run;
  if (!with_curves)
    for (const char* key : {"best_length_so_far", "iteration_best_length", "lost_ants_per_iteration", "iteration_end_ms"})
      j.erase(key);
  if (!with_path)
    for (const char* key : {"path", "smoothed_path", "islands"}) j.erase(key);
  else if (run.smoothed_path == run.path)
    j.erase("smoothed_path");  // not smoothed: the same cells twice
  return j;
}

RunRecord runRecordFromJson(nlohmann::json j) {
  eaci::report::nullsToInfinity(j);
  RunRecord run = j.get<RunRecord>();
  if (!j.contains("smoothed_path")) run.smoothed_path = run.path;  // toJson leaves it out when equal
  return run;
}

}  // namespace eaci_bench
