// Everything a ROS global planner does between "here is a copy of the costmap's cells and its
// frame" and "here is the route": the configuration in force, the planner's kept buffers and
// landmarks, the time limit, cancellation, the robot's own cell, replay files on failure, and
// an exception barrier. No ROS headers (dlux and nav2 split their planners the same way): the
// move_base plugin and the planner node are adapters around it (src/ros/ros_planner.hpp), and
// it is tested without ROS, under ThreadSanitizer, with injected allocation failures.
//
// Locks: plan() takes the planning turn (one plan at a time), configure() and configuration()
// a short configuration lock, cancel() the cancellation's own. None of them is held while
// another is taken, none is held while the caller's costmap lock is taken (the plugins take the
// costmap's lock before they call plan(), or copy the costmap before), and plan() takes no
// costmap lock: the only order is the costmap's, then ours, so no cycle can close.
#pragma once

#include <Eigen/Core>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "costmap_mirror.hpp"
#include "costmap_replay.hpp"
#include "costmap_source.hpp"
#include "costmap_snapshot.hpp"
#include "costmap_view.hpp"
#include "eaci/planner.hpp"
#include "plan_cancellation.hpp"
#include "plan_outcome.hpp"
#include "planner_options.hpp"
#include "replay_writer.hpp"

namespace eaci_service {

// Why a plan stopped before it was done.
enum class StopReason { kNone, kTimeLimit, kCancelled, kShutdown };
const char* toString(StopReason reason);
// The outcome of a plan that `reason` stopped before any route was found (kInternalError for kNone).
PlanOutcome stoppedOutcome(StopReason reason);

enum class LogLevel { kDebug, kInfo, kWarn, kError };
// Where the service's log lines go (the adapters: rosconsole). Called on the planning thread,
// the replay writer's thread or a configuring thread; must be thread-safe.
using Logger = std::function<void(LogLevel, const std::string&)>;

// Fixed for the service's life (read once at start).
struct ServiceSettings {
  std::string who = "eaci_planner";  // starts every log line
  std::string save_costmap_dir = "/tmp";
  bool save_costmap_on_failure = false;  // save the costmap of every failed plan, off the planning thread
  int save_costmap_keep = 10;            // newest replays kept per kind (0 = all)
  std::function<bool()> shutting_down;   // e.g. !ros::ok(); asked like the time limit
  // Tests only: change result.smoothed_path, and the poses made from it, before the check of
  // what goes out (seams to inject a smoother's or a pose's defect); empty in the plugin and the node.
  std::function<void(eaci::CellPath&)> smoothed_path_hook;
  std::function<void(std::vector<Eigen::Vector2d>&)> poses_hook;
  // How landmarks are made (tests: a maker that blocks or fails); empty: Landmarks::compute.
  eaci::LandmarkCache::Maker landmark_maker;
  // The costmaps come from costmap_2d (the plugins), which empties a costmap it resizes until its
  // next update: plan on one emptied by a resize as the last filled one showed it, while that one
  // was read at most stand_in_max_age seconds ago (emptied_costmap.hpp). Off for the node's maps;
  // the plugins' ~stand_in_for_emptied_costmaps (default true) switches it.
  bool stand_in_for_emptied_costmaps = false;
  double stand_in_max_age = 5.0;
};

struct PlanRequest {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  // m, in the costmap's frame
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();
  // m; < 0: default_tolerance. The route ends on the cell nearest the goal within it that the
  // start can reach (navfn's rule): the goal itself when free and reachable.
  double tolerance = -1.0;
  // rad, in the costmap's frame (its origin's yaw ignored, as positions): the robot's yaw and the
  // goal's; NaN: none. With turn_cost > 0 the goal's is priced, the robot's is not.
  double start_yaw = std::numeric_limits<double>::quiet_NaN();
  double goal_yaw = std::numeric_limits<double>::quiet_NaN();
  bool record_pheromone = false;  // with visualize_pheromone, fill result.pheromone (someone listens)
  // When the caller's call began (makePlan entered, before the costmap's lock and any copy):
  // max_planning_time counts from it. Default (the epoch) or later than plan()'s entry: from
  // plan()'s entry.
  std::chrono::steady_clock::time_point called_at{};
};

// Where a plan's time went, in milliseconds (steady clock), step by step: for profiles
// (describePhases; the plugins log it at DEBUG), never for decisions.
struct PlanPhases {
  double wait = 0.0;       // for the planning turn (another plan in progress)
  double costmap = 0.0;    // the planner's copy brought up to the costmap (CostmapMirror::sync), or the stand-in
  bool afresh = false;     //   made anew (first plan, new frame or interpretation)
  std::size_t rows_read = 0, rows_changed = 0;  //   costmap rows compared or copied, and those that differed
  double start = 0.0;      // the start's way out of the inflated band
  double goal = 0.0;       // the free cell nearest the goal
  eaci::PlanTimes core;    // the search (with the landmarks' check), the colony, smoothing
  double tolerance = 0.0;  // no route to the goal: the flood for the reachable cell and the second plan
  double finish = 0.0;     // the grid route's check, the poses that go out made and checked (route_finish.hpp)
  double total = 0.0;      // from the caller's entry (PlanRequest::called_at, else plan()'s) to return
};
// "total 1.234 ms: wait 0.001, costmap 0.002 (12 of 4096 rows read, 3 changed), ..." on one line.
std::string describePhases(const PlanPhases& phases);

struct PlanReply {
  // Why the plan ended as it did, set on every path (kOk: a route, possibly the best so far
  // when a stop came after one was found: stopped_by says so). Adapters decide from this.
  PlanOutcome outcome = PlanOutcome::kInternalError;
  bool ok() const { return outcome == PlanOutcome::kOk; }
  std::string error;            // one line (for people) when !ok()
  // The core's result: result.path the planner's 8-connected route, result.smoothed_path its
  // line-of-sight shortcut, the corners of what goes out unless sent_grid_route.
  eaci::PlanResult result;
  eaci::MapFrame frame;         // the costmap's frame the cells are in
  std::string frame_id;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();  // where the route ends: the goal, or the reachable cell within tolerance
  // The positions of the poses that go out, in the costmap's frame, each segment between two of
  // them checked against the costmap planned on (route_finish.hpp): the start's position first,
  // `goal` last, at most one cell apart. The adapters add headings only.
  std::vector<Eigen::Vector2d> poses;
  // The smoothed route's poses failed the check (a smoother's defect, said at WARN): the grid route's went out.
  bool sent_grid_route = false;
  StopReason stopped_by = StopReason::kNone;
  int start_cells_opened = 0;   // the robot stood in the inflated band: cells opened to leave it
  // The costmap was emptied by a resize: the plan ran on the last filled one, placed into its frame.
  bool stood_in_for_emptied = false;
  RosPlannerOptions options;    // the options the plan was made with (orientation_mode, publish_plan, ...)
  PlanPhases phases;
};

class PlanningService {
 public:
  PlanningService(ServiceSettings settings, Logger log);
  ~PlanningService();
  PlanningService(const PlanningService&) = delete;
  PlanningService& operator=(const PlanningService&) = delete;

  // The parameters later plans use. A non-empty `error` (one sentence naming the parameter)
  // refuses every plan with it until a configuration without one arrives.
  void configure(const eaci::Parameters& params, const RosPlannerOptions& options, const std::string& error) noexcept;
  struct Configuration {
    eaci::Parameters params;
    RosPlannerOptions options;
    std::string error;
    std::uint64_t generation = 0;  // counts configure() calls: a route kept across plans needs the same one
  };
  Configuration configuration() const;

  // Plans on `costmap`, borrowed for the call (its cells valid and unchanged until it returns:
  // the plugin holds the costmap's lock), `changes` what changed in it since the previous plan
  // as far as the caller knows. The service reads only what changed into its own copy
  // (CostmapMirror), which it may change (opening the robot's way out of the band). Never
  // throws: every failure, an allocation failure included, is a reply with its outcome (!ok())
  // and the reason, and the next plan works. A failed plan is not logged here: the adapter logs
  // the reply's outcome and sentence (the service logs only what the reply does not carry: a
  // start opened, a goal moved, landmarks). Returns within max_planning_time (the time spent
  // waiting for another plan to finish counts), after ~cancel, or when settings.shutting_down
  // says so, with the best route so far or a failure.
  PlanReply plan(const CostmapView& costmap, const PlanRequest& request,
                 const CostmapChanges& changes = CostmapChanges::unknown()) noexcept;
  // The same on a copy (the planner node's maps, the ~make_plan service): nothing is known of
  // what changed, so every row is compared with the service's copy.
  PlanReply plan(const CostmapSnapshot& costmap, const PlanRequest& request) noexcept {
    return plan(CostmapView::of(costmap), request);
  }

  // The changes the caller took from its keeper for a plan it did not ask for after all (a pose
  // in another frame): the next plan compares every row. Any thread.
  void changesNotRead() noexcept { source_.changesNotRead(); }

  // Asks the plan in progress to stop with the best route so far; false when none runs.
  bool cancel() noexcept;

  // Saves `costmap` with the last request planned and the configuration for replay (on the
  // calling thread). "" and `files` filled, or the reason it failed.
  std::string saveCostmap(CostmapSnapshot costmap, ReplayFiles& files) noexcept;

 private:
  // One plan, holding the turn: its steps below, in order, on a PlanState they share.
  PlanReply planLocked(const CostmapView& costmap, const CostmapChanges& changes, const PlanRequest& request,
                       const Configuration& config, const std::function<bool()>& should_stop,
                       const std::atomic<int>& stop_reason);
  struct PlanState;
  struct Refusal {  // why a step ends the plan
    PlanOutcome outcome;
    std::string why;
  };
  void renewWorkspaceIfSuspect();  // a plan that threw: a new workspace, the copy made afresh
  std::optional<Refusal> checkCostmapAndParameters(PlanState& plan);
  std::optional<Refusal> readCostmap(PlanState& plan, const CostmapChanges& changes);
  std::optional<Refusal> placeStart(PlanState& plan);
  std::optional<Refusal> placeGoal(PlanState& plan);
  std::optional<Refusal> searchRoute(PlanState& plan);
  std::optional<Refusal> makePoses(PlanState& plan);
  // The plan as ~last_plan and ~save_costmap replay it; a failed one's costmap saved when asked.
  void recordPlan(const PlanState& plan);
  // Landmarks for the plan on a costmap in `frame`: `requested`, none on a rolling window.
  void useLandmarksFor(const eaci::MapFrame& frame, int requested);
  // After the plan: fewer landmarks than asked (their memory cap) or a failure to make them,
  // each said once, as the landmark cache reports it.
  void reportLandmarks(const eaci::MapFrame& frame);
  void say(LogLevel level, const std::string& line) const noexcept;
  std::vector<std::string> replayNotes(const std::string& note, const Configuration& config) const;

  const ServiceSettings settings_;
  const Logger log_;

  mutable std::mutex config_mutex_;
  Configuration config_;  // under config_mutex_

  // One plan at a time (a flag under a mutex and a condition variable, waited for until the
  // plan's deadline; a std::timed_mutex would do, but ThreadSanitizer cannot see its
  // pthread_mutex_clocklock); the workspace is made again after a plan that threw (its buffers
  // may be half made; the old one is destroyed on a thread of its own, which no plan waits for).
  std::mutex turn_mutex_;
  std::condition_variable turn_free_;
  bool planning_ = false;  // under turn_mutex_; the members below marked "the plan's" belong to the plan holding the turn
  std::unique_ptr<eaci::PlannerWorkspace> workspace_;  // the plan's
  bool workspace_suspect_ = false;  // under turn_mutex_ when set, the plan's when read: a plan threw, make it afresh
  // Rolling-window costmaps (local costmaps) move every update: landmarks would never hold.
  std::optional<eaci::MapFrame> last_frame_;  // the plan's
  int moves_in_a_row_ = 0;                    // the plan's
  bool rolling_ = false;                      // the plan's
  CostmapSource source_;                      // the plan's: the costmap as of the last plan (changesNotRead: any thread)
  int landmarks_reported_ = -1;               // the plan's: the count last said (-1: none said)
  std::string landmark_error_reported_;       // the plan's
  PlanCancellation cancellation_;

  mutable std::mutex last_plan_mutex_;
  std::optional<PlanRecord> last_plan_;  // under last_plan_mutex_

  std::unique_ptr<ReplayWriter> writer_;
};

}  // namespace eaci_service
