#include "costmap_replay.hpp"

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "eaci/planner/parameter_file.hpp"
#include "eaci/io/map_server_writer.hpp"
#include "eaci/io/text.hpp"

namespace eaci_service {
namespace {

namespace fs = std::filesystem;

std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char ch : text) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

std::string xy(const Eigen::Vector2d& p) { return eaci::exactNumber(p.x()) + "," + eaci::exactNumber(p.y()); }

}  // namespace

std::string describeOutcome(PlanOutcome outcome, const std::string& error, const eaci::PlanResult& result,
                            double resolution) {
  if (outcome != PlanOutcome::kOk) return std::string("failed (") + toName(outcome) + "): " + error;
  return "route: cost " + eaci::formatNumber(result.cost, 6) + ", length " + eaci::formatNumber(result.length, 6) +
         " cells (" + eaci::formatNumber(result.length * resolution, 4) + " m), " + std::to_string(result.path.size()) +
         " cells, smoothed length " + eaci::formatNumber(result.smoothed_length, 6) + " cells";
}

std::string timestampedName(const std::string& prefix) {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto millis =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm local{};
  localtime_r(&seconds, &local);
  char text[64];
  std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &local);
  char with_millis[80];
  std::snprintf(with_millis, sizeof with_millis, "%s-%03d", text, static_cast<int>(millis));
  return prefix + "_" + with_millis;
}

ReplayFiles saveCostmapForReplay(const std::string& directory, const std::string& base_name,
                                 const CostmapSnapshot& costmap, const eaci::Parameters& params,
                                 eaci::Algorithm algorithm, const std::optional<PlanRecord>& request,
                                 const std::vector<std::string>& notes) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error) throw std::runtime_error("cannot create the directory " + directory + ": " + error.message());
  const fs::path base = fs::path(directory) / base_name;
  ReplayFiles files;
  files.map_yaml = base.string() + ".yaml";
  files.params_yaml = base.string() + ".params.yaml";

  {
    std::ofstream out(files.params_yaml, std::ios::trunc);
    out << "# the parameters of the plan, for eaci_plan --params\n" << eaci::parameterYaml(params);
    out.close();
    if (!out) throw std::runtime_error("cannot write " + files.params_yaml);
  }

  std::vector<std::string> comments = notes;
  if (request) {
    files.command = "eaci_plan --map " + shellQuoted(files.map_yaml) + " --start-xy=" + xy(request->start) +
                    " --goal-xy=" + xy(request->goal) + " --algorithm " + eaci::toString(algorithm) + " --params " +
                    shellQuoted(files.params_yaml);
    if (request->tolerance > 0) files.command += " --tolerance " + eaci::exactNumber(request->tolerance);
    comments.push_back("request: start (" + xy(request->start) + ") m, goal (" + xy(request->goal) + ") m, tolerance " +
                       eaci::exactNumber(request->tolerance) + " m, in frame " + costmap.frame_id);
    comments.push_back(request->outcome);
    comments.push_back("replay: " + files.command);
  }
  const eaci::GridView cells(costmap.cells.data(), costmap.frame.width, costmap.frame.height,
                             costmap.order);
  const eaci::SavedMapFiles saved = eaci::saveRawMap(files.map_yaml, cells, costmap.frame, comments);
  files.map_image = saved.image_path;
  return files;
}

}  // namespace eaci_service
