#include "planning_service.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <exception>
#include <new>
#include <sstream>
#include <utility>

#include "eaci/grid/nearest_free.hpp"
#include "eaci/search/nearest_reachable.hpp"
#include "eaci/io/text.hpp"
#include "route_defect.hpp"
#include "route_finish.hpp"
#include "start_cell.hpp"

namespace eaci_service {
namespace {

std::string where(const Eigen::Vector2d& p) {
  return "(" + eaci::formatNumber(p.x(), 3) + ", " + eaci::formatNumber(p.y(), 3) + ")";
}

std::string sizeOf(const eaci::MapFrame& frame) {
  return std::to_string(frame.width) + " x " + std::to_string(frame.height) + " cells";
}

// The outcome of a plan the core refused or found no route for (not stopped): typed where it
// arose, never read from its sentence. `goal_free`: the goal cell itself may be crossed.
PlanOutcome outcomeOf(eaci::PlanStatus status, bool goal_free) {
  switch (status) {
    case eaci::PlanStatus::kSuccess: return PlanOutcome::kOk;
    case eaci::PlanStatus::kNoPath: return goal_free ? PlanOutcome::kNoPath : PlanOutcome::kGoalBlocked;
    case eaci::PlanStatus::kStopped: return PlanOutcome::kInternalError;  // the stop reason decides (stoppedOutcome)
    case eaci::PlanStatus::kStartOffMap: return PlanOutcome::kStartOffMap;
    case eaci::PlanStatus::kStartBlocked: return PlanOutcome::kStartBlocked;
    case eaci::PlanStatus::kGoalOffMap: return PlanOutcome::kGoalOffMap;
    case eaci::PlanStatus::kGoalBlocked: return PlanOutcome::kGoalBlocked;
    case eaci::PlanStatus::kInvalidParameters: return PlanOutcome::kBadParameters;
    case eaci::PlanStatus::kInvalidMap: return PlanOutcome::kBadCostmap;
  }
  return PlanOutcome::kInternalError;
}

// Costmaps larger than this are refused: 32-bit cell indices, and the planner's per-cell
// buffers (a few tens of bytes a cell) must fit a robot's memory.
constexpr std::size_t kMaxCostmapCells = eaci::kMaxGridCells;

// Why `costmap` cannot be planned on (empty, an unusable frame, over the cap, a copy that does
// not hold the cells it claims, no cells), or "".
std::string costmapProblem(const CostmapView& costmap) {
  const eaci::MapFrame& frame = costmap.frame;
  if (frame.width <= 0 || frame.height <= 0) return "the costmap is empty (" + sizeOf(frame) + ")";
  if (!std::isfinite(frame.resolution) || !(frame.resolution > 0) || !frame.origin.allFinite())
    return "the costmap's resolution " + eaci::formatNumber(frame.resolution) + " m or origin is not usable";
  const std::size_t cell_count = static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height);
  if (cell_count > kMaxCostmapCells)
    return "the costmap of " + sizeOf(frame) + " is larger than the planner's cap of " +
           std::to_string(kMaxCostmapCells) + " cells";
  if (costmap.cells_held != CostmapView::kUnchecked && costmap.cells_held != cell_count)
    return "the costmap copy holds " + std::to_string(costmap.cells_held) + " cells, not the " + sizeOf(frame) +
           " it claims";
  if (costmap.cells == nullptr) return "the costmap of " + sizeOf(frame) + " came without its cells";
  return "";
}

}  // namespace

const char* toString(StopReason reason) {
  switch (reason) {
    case StopReason::kNone: return "not stopped";
    case StopReason::kTimeLimit: return "max_planning_time ran out";
    case StopReason::kCancelled: return "cancelled";
    case StopReason::kShutdown: return "shutting down";
  }
  return "?";
}

PlanOutcome stoppedOutcome(StopReason reason) {
  switch (reason) {
    case StopReason::kTimeLimit: return PlanOutcome::kTimeLimit;
    case StopReason::kCancelled: return PlanOutcome::kCancelled;
    case StopReason::kShutdown: return PlanOutcome::kShutdown;
    case StopReason::kNone: break;
  }
  return PlanOutcome::kInternalError;
}

PlanningService::PlanningService(ServiceSettings settings, Logger log)
    : settings_(std::move(settings)),
      log_(std::move(log)),
      source_({settings_.stand_in_for_emptied_costmaps, settings_.stand_in_max_age},
              [this](const std::string& line, bool warn) { say(warn ? LogLevel::kWarn : LogLevel::kInfo, line); }) {
  config_.params = rosDefaultParameters();
  writer_ = std::make_unique<ReplayWriter>(settings_.save_costmap_dir, settings_.save_costmap_keep,
                                           [this](const std::string& line, bool ok) {
                                             say(ok ? LogLevel::kInfo : LogLevel::kError, line);
                                           });
}

PlanningService::~PlanningService() {
  cancel();
  std::unique_lock<std::mutex> lock(turn_mutex_);  // a plan still running ends first
  turn_free_.wait(lock, [this] { return !planning_; });
  workspace_.reset();
  writer_.reset();
}

void PlanningService::say(LogLevel level, const std::string& line) const noexcept {
  try {
    if (log_) log_(level, settings_.who + ": " + line);
  } catch (...) {  // a log line is not worth a failed plan
  }
}

void PlanningService::configure(const eaci::Parameters& params, const RosPlannerOptions& options,
                                const std::string& error) noexcept {
  try {
    Configuration config{params, options, error};
    std::lock_guard<std::mutex> lock(config_mutex_);
    config.generation = config_.generation + 1;
    config_ = std::move(config);
  } catch (...) {  // no memory for the copy: plans are refused until a configuration is stored
    std::lock_guard<std::mutex> lock(config_mutex_);
    try {
      config_.error = "the new parameters could not be stored (out of memory)";
    } catch (...) {  // not even the sentence: the configuration in force stays
    }
  }
}

PlanningService::Configuration PlanningService::configuration() const {
  std::lock_guard<std::mutex> lock(config_mutex_);
  return config_;
}

bool PlanningService::cancel() noexcept {
  try {
    return cancellation_.cancel();
  } catch (...) {
    return false;
  }
}

std::string describePhases(const PlanPhases& p) {
  const auto ms = [](double v) { return eaci::formatNumber(v, 3); };
  std::string line = "total " + ms(p.total) + " ms: wait " + ms(p.wait) + ", costmap " + ms(p.costmap) + " (" +
                     (p.afresh ? "made afresh, " : "") + std::to_string(p.rows_read) + " rows read, " +
                     std::to_string(p.rows_changed) + " changed), start " + ms(p.start) + ", goal " + ms(p.goal) +
                     ", search " + ms(p.core.search) + ", colony " + ms(p.core.colony) + ", smoothing " +
                     ms(p.core.smoothing);
  if (p.tolerance > 0) line += ", tolerance " + ms(p.tolerance);
  return line + ", finish " + ms(p.finish);
}

PlanReply PlanningService::plan(const CostmapView& costmap, const PlanRequest& request,
                                const CostmapChanges& changes) noexcept {
  const auto entered = std::chrono::steady_clock::now();
  // The time limit counts from the caller's entry (its costmap lock and copy included).
  const auto started = request.called_at != std::chrono::steady_clock::time_point{} && request.called_at < entered
                           ? request.called_at
                           : entered;
  PlanReply reply;
  const auto fail = [&](const std::string& why) noexcept {
    try {
      reply = PlanReply();
      reply.outcome = PlanOutcome::kInternalError;
      reply.error = why;
    } catch (...) {
    }
  };
  try {
    const Configuration config = configuration();
    if (!config.error.empty()) {
      source_.changesNotRead();
      reply.outcome = PlanOutcome::kBadParameters;
      reply.error = config.error + ": refusing to plan until it is fixed";
      return reply;
    }
    // Asked by every loop of the plan that grows with the map, on any of its threads.
    const double limit = config.options.max_planning_time;
    const bool timed = limit > 0;
    const auto deadline = started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                        std::chrono::duration<double>(timed ? limit : 0.0));
    std::atomic<int> stop_reason{static_cast<int>(StopReason::kNone)};
    const std::atomic<bool>& cancelled = *cancellation_.flag();
    const std::function<bool()> should_stop = [&]() {
      if (stop_reason.load(std::memory_order_relaxed) != static_cast<int>(StopReason::kNone)) return true;
      StopReason reason = StopReason::kNone;
      if (settings_.shutting_down && settings_.shutting_down()) reason = StopReason::kShutdown;
      else if (cancelled.load(std::memory_order_relaxed)) reason = StopReason::kCancelled;
      else if (timed && std::chrono::steady_clock::now() >= deadline) reason = StopReason::kTimeLimit;
      if (reason == StopReason::kNone) return false;
      int none = static_cast<int>(StopReason::kNone);
      stop_reason.compare_exchange_strong(none, static_cast<int>(reason));
      return true;
    };
    {
      std::unique_lock<std::mutex> lock(turn_mutex_);
      const auto free = [this] { return !planning_; };
      if (!timed) {
        turn_free_.wait(lock, free);
      } else if (!turn_free_.wait_until(lock, deadline, free)) {
        lock.unlock();
        source_.changesNotRead();
        reply.outcome = PlanOutcome::kTimeLimit;
        reply.error = "another plan held the planner for the whole max_planning_time (" + eaci::formatNumber(limit) + " s)";
        return reply;
      }
      planning_ = true;
    }
    struct Turn {  // gives the turn back however the plan ends; a plan that threw leaves its
                   // workspace suspect (its buffers may be half made) before the next plan can start
      PlanningService& service;
      const int exceptions = std::uncaught_exceptions();
      ~Turn() {
        {
          std::lock_guard<std::mutex> lock(service.turn_mutex_);
          if (std::uncaught_exceptions() > exceptions) service.workspace_suspect_ = true;
          service.planning_ = false;
        }
        service.turn_free_.notify_one();
      }
    } turn{*this};
    const PlanCancellation::Scope in_progress(cancellation_);
    const double waited = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - entered).count();
    reply = planLocked(costmap, changes, request, config, should_stop, stop_reason);
    reply.phases.wait = waited;
    reply.phases.total = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  } catch (const std::bad_alloc&) {
    source_.changesNotRead();
    fail("out of memory while planning (std::bad_alloc): no plan; the planner's buffers are made afresh for the next one");
  } catch (const std::exception& e) {
    source_.changesNotRead();
    fail(std::string("planning failed: ") + e.what());
  } catch (...) {
    source_.changesNotRead();
    fail("planning failed with an unknown exception");
  }
  return reply;
}

// One plan's state while it holds the turn, shared by planLocked's steps.
struct PlanningService::PlanState {
  using Clock = std::chrono::steady_clock;
  PlanState(const CostmapView& costmap_in, const PlanRequest& request_in, const Configuration& config_in,
            const std::function<bool()>& should_stop_in, const std::atomic<int>& stop_reason_in)
      : costmap(costmap_in), request(request_in), config(config_in), should_stop(should_stop_in),
        stop_reason(stop_reason_in) {}
  const CostmapView& costmap;
  const PlanRequest& request;
  const Configuration& config;
  const eaci::MapFrame& frame() const { return costmap.frame; }
  const eaci::Parameters& params() const { return config.params; }
  const RosPlannerOptions& options() const { return config.options; }
  const std::function<bool()>& should_stop;  // asked by every loop that grows with the map
  const std::atomic<int>& stop_reason;       // why should_stop said stop, once it did
  PlanReply reply;
  double tolerance = 0.0;                    // m: the request's, else default_tolerance
  bool changes_read = false;                 // the keeper's reported changes went into the copy
  CostmapMirror* mirror = nullptr;           // the copy planned on, once read
  eaci::CellInterpretation interpretation;
  eaci::Cell start_cell, goal_cell, target;  // target: where the route ends (the goal, or a cell within the tolerance)
  bool goal_free = false;
  Clock::time_point phase_start = Clock::now();

  StopReason stopped() const { return static_cast<StopReason>(stop_reason.load()); }
  // Adds the time since the last lap to `into`.
  void lap(double& into) {
    const Clock::time_point now = Clock::now();
    into += std::chrono::duration<double, std::milli>(now - phase_start).count();
    phase_start = now;
  }
  // The plan ends because should_stop said so while doing `what`.
  Refusal stoppedWhile(const std::string& what) const {
    return {stoppedOutcome(stopped()), std::string(toString(stopped())) + " while " + what};
  }
};

// A plan, step by step; each step either goes on (nullopt) or ends the plan with its reason.
PlanReply PlanningService::planLocked(const CostmapView& costmap, const CostmapChanges& changes,
                                      const PlanRequest& request, const Configuration& config,
                                      const std::function<bool()>& should_stop, const std::atomic<int>& stop_reason) {
  renewWorkspaceIfSuspect();
  PlanState plan(costmap, request, config, should_stop, stop_reason);
  plan.reply.options = config.options;
  plan.reply.frame = costmap.frame;
  plan.reply.frame_id = costmap.frame_id;
  plan.reply.goal = request.goal;
  plan.tolerance = request.tolerance >= 0 ? request.tolerance : config.options.default_tolerance;

  std::optional<Refusal> refused = checkCostmapAndParameters(plan);
  if (!refused) refused = readCostmap(plan, changes);  // the copy brought up to the costmap (or the stand-in)
  if (!refused) refused = placeStart(plan);            // the start's cell, opened out of the inflated band
  if (!refused) refused = placeGoal(plan);             // the free cell nearest the goal within the tolerance
  if (!refused) refused = searchRoute(plan);           // the route; else to the reachable cell nearest the goal
  if (!refused) refused = makePoses(plan);             // the poses that go out, every segment checked
  if (refused) {
    if (!plan.changes_read) source_.changesNotRead();
    plan.reply.outcome = refused->outcome;
    plan.reply.error = refused->why;
  } else {
    plan.reply.outcome = PlanOutcome::kOk;
  }
  recordPlan(plan);
  return std::move(plan.reply);
}

void PlanningService::renewWorkspaceIfSuspect() {
  if (!workspace_suspect_ && workspace_) return;
  source_.clear();  // a plan that threw may have left its copy half made
  workspace_suspect_ = false;
  // Its destructor joins the colony's and the search's worker threads, which a loaded machine
  // may schedule late, and move_base holds its costmap lock across the plan: it is destroyed
  // on a thread of its own, which the plan does not wait for (its landmark job is only
  // cancelled, LandmarkCache).
  eaci::destroyOffThisThread(std::move(workspace_));
  workspace_ = std::make_unique<eaci::PlannerWorkspace>();
  landmarks_reported_ = -1;
  landmark_error_reported_.clear();
}

std::optional<PlanningService::Refusal> PlanningService::checkCostmapAndParameters(PlanState& plan) {
  if (const std::string problem = costmapProblem(plan.costmap); !problem.empty())
    return Refusal{PlanOutcome::kBadCostmap, problem};
  if (const std::string invalid = eaci::validationError(plan.params()); !invalid.empty())
    return Refusal{PlanOutcome::kBadParameters, "invalid parameter: " + invalid};
  plan.interpretation =
      eaci::CellInterpretation::costmap(static_cast<std::uint8_t>(plan.params().lethal_cost), plan.params().allow_unknown);
  plan.interpretation.unknown_value = kCostmapUnknown;
  return std::nullopt;
}

std::optional<PlanningService::Refusal> PlanningService::readCostmap(PlanState& plan, const CostmapChanges& changes) {
  // The planner's copy of the costmap, brought up to it where it changed; or, for a costmap
  // costmap_2d has emptied by a resize, the last filled one placed into its frame.
  const CostmapSource::Read read = source_.read(plan.costmap, changes, plan.interpretation,
                                                plan.params().allow_corner_cutting, eaci::costRule(plan.params()), rolling_,
                                                PlanState::Clock::now(), plan.should_stop);
  plan.changes_read = true;  // or, when stopped, put back for the next read (CostmapSource)
  if (read.synced.stopped)
    return plan.stoppedWhile("reading the costmap (" + std::to_string(read.synced.rows_read) + " of " +
                             std::to_string(plan.frame().height) + " rows)");
  plan.mirror = read.mirror;
  plan.reply.stood_in_for_emptied = read.stood_in;
  plan.reply.phases.afresh = read.synced.afresh;
  plan.reply.phases.rows_read = read.synced.rows_read;
  plan.reply.phases.rows_changed = read.synced.rows_changed;
  plan.lap(plan.reply.phases.costmap);
  return std::nullopt;
}

std::optional<PlanningService::Refusal> PlanningService::placeStart(PlanState& plan) {
  const PlanRequest& request = plan.request;
  const auto start_cell = plan.frame().worldToCell(request.start);
  if (!start_cell) return Refusal{PlanOutcome::kStartOffMap, "start " + where(request.start) + " is off the costmap"};
  const auto goal_cell = plan.frame().worldToCell(request.goal);
  if (!goal_cell) return Refusal{PlanOutcome::kGoalOffMap, "goal " + where(request.goal) + " is off the costmap"};
  plan.start_cell = *start_cell;
  plan.goal_cell = *goal_cell;
  const StartCellCheck check = openStartCell(plan.mirror->costmap(), plan.interpretation, *start_cell, plan.should_stop);
  if (!check.ok)
    return Refusal{check.stopped ? stoppedOutcome(plan.stopped()) : check.outcome,
                   "start " + where(request.start) + ": " + check.error};
  for (const eaci::Cell& cell : check.opened) plan.mirror->open(cell, check.opened_cost);  // until the next read
  plan.reply.start_cells_opened = check.cells_opened;
  if (check.cells_opened > 0)
    say(LogLevel::kInfo, "start " + where(request.start) + " is in the inflated band (cost " +
                             std::to_string(check.start_cost) + ", lethal_cost " + std::to_string(plan.params().lethal_cost) +
                             "): planning out of it by the cheapest way (" + std::to_string(check.cells_opened) +
                             " cells), as navfn plans from the robot's cell");
  plan.lap(plan.reply.phases.start);
  return std::nullopt;
}

std::optional<PlanningService::Refusal> PlanningService::placeGoal(PlanState& plan) {
  // The goal tolerance, as navfn's: the route ends on the cell nearest to the goal, within the
  // tolerance, that the start can reach. First the nearest free cell (the goal itself when it is
  // free: no extra work in the normal case); only when no route reaches it, a flood from the
  // start finds the nearest reachable cell (searchRoute: a free cell behind a wall must not win).
  const eaci::GridView view = plan.mirror->view();
  plan.goal_free = view.isFree(plan.goal_cell);
  const std::optional<eaci::Cell> target =
      eaci::nearestFreeCell(view, plan.goal_cell, plan.tolerance / plan.frame().resolution, plan.should_stop);
  if (!target) {
    if (plan.stopped() != StopReason::kNone) return plan.stoppedWhile("looking for a free cell near the goal");
    return Refusal{PlanOutcome::kGoalBlocked, "goal " + where(plan.request.goal) +
                                                  " is in an obstacle and no free cell lies within " +
                                                  eaci::formatNumber(plan.tolerance) + " m of it"};
  }
  plan.target = *target;
  plan.lap(plan.reply.phases.goal);
  return std::nullopt;
}

std::optional<PlanningService::Refusal> PlanningService::searchRoute(PlanState& plan) {
  useLandmarksFor(plan.frame(), plan.options().landmarks);
  eaci::PlanOptions plan_options;
  plan_options.record_pheromone = plan.options().visualize_pheromone && plan.request.record_pheromone;
  plan_options.workspace = workspace_.get();
  plan_options.should_stop = [&should_stop = plan.should_stop](int) { return should_stop(); };
  plan_options.never_worse_than_search = true;  // a lucky ant's detour never reaches the robot
  // With turn_cost > 0 the turn onto the goal's heading is priced too (grid angles are the
  // costmap frame's yaws, y up the rows); the robot's own heading is not (docs/ros.md).
  plan_options.end_headings.goal = eaci::travelHeading(plan.request.goal_yaw, plan.options().orientation_mode);
  // The planners' grid, kept in the mirror: both plans of a goal tolerance and the flood between them search it.
  const eaci::CostGrid& grid = plan.mirror->grid();
  eaci::PlanResult& result = plan.reply.result;
  result = eaci::plan(grid, plan.start_cell, plan.target, plan.options().algorithm, plan.params(), plan_options);
  plan.reply.phases.core = result.times;
  plan.phase_start = PlanState::Clock::now();
  const double radius_cells = plan.tolerance / plan.frame().resolution;
  if (result.status == eaci::PlanStatus::kNoPath && !result.interrupted && radius_cells >= 1) {
    const auto reachable =
        eaci::nearestReachableCell(grid, plan.start_cell, plan.goal_cell, radius_cells, plan.should_stop);
    if (plan.stopped() != StopReason::kNone)
      return plan.stoppedWhile("looking for a cell near the goal that the start can reach");
    if (!reachable)
      return Refusal{plan.goal_free ? PlanOutcome::kNoPath : PlanOutcome::kGoalBlocked,
                     "goal " + where(plan.request.goal) + " cannot be reached from the start, nor any cell within " +
                         eaci::formatNumber(plan.tolerance) + " m of it"};
    if (!(*reachable == plan.target)) {  // else the plan failed for another reason: its error stands
      say(LogLevel::kInfo, "no route reaches " + where(plan.frame().cellToWorld(plan.target)) + ": planning to " +
                               where(plan.frame().cellToWorld(*reachable)) +
                               ", the cell nearest the goal within the tolerance that the start can reach");
      plan.target = *reachable;
      result = eaci::plan(grid, plan.start_cell, plan.target, plan.options().algorithm, plan.params(), plan_options);
    }
  }
  plan.lap(plan.reply.phases.tolerance);
  reportLandmarks(plan.frame());
  if (result.interrupted) plan.reply.stopped_by = plan.stopped();
  if (result.success()) return std::nullopt;
  if (result.status != eaci::PlanStatus::kStopped) return Refusal{outcomeOf(result.status, plan.goal_free), result.error};
  if (plan.reply.stopped_by == StopReason::kTimeLimit)
    return Refusal{PlanOutcome::kTimeLimit, "no route found within max_planning_time (" +
                                                eaci::formatNumber(plan.options().max_planning_time) + " s)"};
  return Refusal{stoppedOutcome(plan.reply.stopped_by), std::string(toString(plan.reply.stopped_by)) + " after " +
                                                            std::to_string(result.iterations_run) +
                                                            " iterations, before a route was found"};
}

std::optional<PlanningService::Refusal> PlanningService::makePoses(PlanState& plan) {
  PlanReply& reply = plan.reply;
  const eaci::GridView view = plan.mirror->view();
  const bool corner_cutting = plan.params().allow_corner_cutting;
  const std::string defect = routeDefect(view, reply.result.path, plan.start_cell, plan.target, corner_cutting);
  if (!defect.empty())
    return Refusal{PlanOutcome::kInternalError, "internal error: the planner's route is not drivable (" + defect + "); no plan"};
  if (!(plan.target == plan.goal_cell)) reply.goal = plan.frame().cellToWorld(plan.target);
  // What goes out: the smoothed route's poses, every segment between two of them checked; if
  // the smoother got one wrong, the grid route's (just checked cell by cell).
  if (settings_.smoothed_path_hook) settings_.smoothed_path_hook(reply.result.smoothed_path);
  const FinishedRoute finished = finishRoute(view, plan.frame(), reply.result.smoothed_path, reply.result.path,
                                             plan.request.start, reply.goal, corner_cutting, settings_.poses_hook);
  plan.lap(reply.phases.finish);
  if (finished.poses.empty())
    return Refusal{PlanOutcome::kInternalError, "internal error: no route's poses pass the last check (" +
                                                    finished.defect + "); no plan"};
  if (finished.grid_route) {
    say(LogLevel::kWarn, "the smoothed route's poses are not drivable (" + finished.smoothed_defect +
                             "): sending the grid route's instead");
    reply.result.smoothed_path = reply.result.path;
    reply.result.smoothed_length = reply.result.length;
  }
  reply.poses = finished.poses;
  reply.sent_grid_route = finished.grid_route;
  const bool colony_replaced = std::isfinite(reply.result.colony_combined_cost);
  if (colony_replaced)  // the usual case on a robot (docs/ros.md, "What a robot gets"): at DEBUG
    say(LogLevel::kDebug, "the colony's best route scored " + eaci::formatNumber(reply.result.colony_combined_cost) +
                             ", worse than the cheapest route the islands sit on: sending that route");
  if (reply.stopped_by != StopReason::kNone)
    say(LogLevel::kInfo, std::string(toString(reply.stopped_by)) + " after " +
                             std::to_string(reply.result.iterations_run) + " iterations: returning " +
                             (!reply.result.route_from_search ? "the best route so far"
                              : colony_replaced ? "the cheapest route the islands sit on (cheaper than the colony's best)"
                                                : "the cheapest route the islands sit on (no ant had arrived yet)"));
  return std::nullopt;
}

void PlanningService::recordPlan(const PlanState& plan) {
  PlanRecord record;
  record.start = plan.request.start;
  record.goal = plan.request.goal;
  record.tolerance = plan.tolerance;
  record.outcome = describeOutcome(plan.reply.outcome, plan.reply.error, plan.reply.result, plan.frame().resolution);
  if (!plan.reply.ok() && settings_.save_costmap_on_failure && plan.mirror != nullptr &&
      !plan.mirror->costmap().cells.empty()) {
    ReplayJob job;
    job.prefix = "eaci_failed_plan";
    job.params = plan.params();
    job.algorithm = plan.options().algorithm;
    job.request = record;
    job.notes = replayNotes("the costmap of a failed plan", plan.config);
    job.costmap = plan.mirror->costmap();  // as planned on: a start in the band opened
    if (!writer_->submit(std::move(job))) say(LogLevel::kWarn, "could not hand the failed plan's costmap to the writer");
  }
  std::lock_guard<std::mutex> lock(last_plan_mutex_);
  last_plan_ = std::move(record);
}

void PlanningService::useLandmarksFor(const eaci::MapFrame& frame, int requested) {
  if (last_frame_ && last_frame_->width == frame.width && last_frame_->height == frame.height &&
      last_frame_->resolution == frame.resolution) {
    moves_in_a_row_ = last_frame_->origin != frame.origin ? moves_in_a_row_ + 1 : 0;
  } else {
    moves_in_a_row_ = 0;
  }
  last_frame_ = frame;
  if (!rolling_ && requested > 0 && moves_in_a_row_ >= 2) {
    rolling_ = true;
    say(LogLevel::kInfo, "the costmap moves with the robot (a rolling window): no landmarks on it, they would be made "
                         "again for every plan");
  }
  workspace_->meeting.useLandmarks(rolling_ ? 0 : requested, settings_.landmark_maker);
}

void PlanningService::reportLandmarks(const eaci::MapFrame& frame) {
  const eaci::LandmarkCache* cache = workspace_->meeting.landmarkCache();
  if (cache == nullptr) return;
  const int in_use = cache->countInUse();
  if (in_use < cache->count() && in_use != landmarks_reported_)
    say(LogLevel::kWarn, std::to_string(cache->count()) + " landmarks do not fit on " + sizeOf(frame) + ": making " +
                             std::to_string(in_use) + " (their tables are capped at " +
                             std::to_string(eaci::kMaxLandmarkBytes >> 20) + " MiB)");
  landmarks_reported_ = in_use;
  const std::string error = cache->lastError();
  if (!error.empty() && error != landmark_error_reported_)
    say(LogLevel::kWarn, error + "; planning without landmarks until they are made");
  landmark_error_reported_ = error;
}

std::vector<std::string> PlanningService::replayNotes(const std::string& note, const Configuration& config) const {
  return {"saved by " + settings_.who + ": " + note,
          "costmap_2d costs: 0 free, 1..252 cost, 253/254 obstacles, 255 unknown (lethal_cost " +
              std::to_string(config.params.lethal_cost) + ", allow_unknown " +
              (config.params.allow_unknown ? "true" : "false") + ")",
          "the planner's max_planning_time was " + eaci::formatNumber(config.options.max_planning_time) +
              " s; the replay runs every iteration; a start in the inflated band was opened as the planner did"};
}

std::string PlanningService::saveCostmap(CostmapSnapshot costmap, ReplayFiles& files) noexcept {
  try {
    const Configuration config = configuration();
    ReplayJob job;
    job.prefix = "eaci_costmap";
    job.params = config.params;
    job.algorithm = config.options.algorithm;
    {
      std::lock_guard<std::mutex> lock(last_plan_mutex_);
      job.request = last_plan_;
    }
    job.notes = replayNotes(job.request ? "the costmap when ~save_costmap was called; the request below is the last one planned"
                                        : "the costmap when ~save_costmap was called; no plan had been asked for",
                            config);
    job.costmap = std::move(costmap);
    files = writer_->writeNow(job);
    say(LogLevel::kInfo, "saved the costmap as " + files.map_yaml + " (+ " + files.map_image + ", parameters " +
                             files.params_yaml + ")" + (files.command.empty() ? "" : "; replay: " + files.command));
    return "";
  } catch (const std::exception& e) {
    say(LogLevel::kError, std::string("cannot save the costmap: ") + e.what());
    try {
      return e.what();
    } catch (...) {
    }
  } catch (...) {
  }
  try {
    return "cannot save the costmap";
  } catch (...) {
    return {};  // not even the sentence fits: an empty reason still says it failed (files are empty)
  }
}

}  // namespace eaci_service
