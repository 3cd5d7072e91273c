#include "run_record.hpp"

#include "common/json_number.hpp"

namespace eaci_bench {

nlohmann::json toJson(const RunRecord& run, bool with_curves, bool with_path) {
  nlohmann::json j = run;
  if (!with_curves)
    for (const char* key : {"best_length_so_far", "iteration_best_length", "lost_ants_per_iteration", "iteration_end_ms"})
      j.erase(key);
  if (!with_path)
    for (const char* key : {"path", "islands"}) j.erase(key);
  return j;
}

RunRecord runRecordFromJson(nlohmann::json j) {
  eaci::report::nullsToInfinity(j);
  return j.get<RunRecord>();
}

}  // namespace eaci_bench
