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
  const auto started = std::chrono::steady_clock::now();
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
    const double waited = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
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

PlanReply PlanningService::planLocked(const CostmapView& costmap, const CostmapChanges& changes,
                                      const PlanRequest& request, const Configuration& config,
                                      const std::function<bool()>& should_stop, const std::atomic<int>& stop_reason) {
  using Clock = std::chrono::steady_clock;
  Clock::time_point phase_start = Clock::now();
  const auto phaseDone = [&phase_start](double& into) {
    const Clock::time_point now = Clock::now();
    into += std::chrono::duration<double, std::milli>(now - phase_start).count();
    phase_start = now;
  };
  if (workspace_suspect_ || !workspace_) {
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
  const eaci::Parameters& params = config.params;
  const RosPlannerOptions& options = config.options;
  PlanReply reply;
  reply.options = options;
  reply.frame = costmap.frame;
  reply.frame_id = costmap.frame_id;
  reply.goal = request.goal;
  const double tolerance = request.tolerance >= 0 ? request.tolerance : options.default_tolerance;
  PlanRecord record;
  record.start = request.start;
  record.goal = request.goal;
  record.tolerance = tolerance;
  const CostmapMirror* planned_on = nullptr;  // the copy the plan read, once made
  const auto finish = [&](PlanReply& done) -> PlanReply& {
    record.outcome = describeOutcome(done.outcome, done.error, done.result, costmap.frame.resolution);
    {
      std::lock_guard<std::mutex> lock(last_plan_mutex_);
      last_plan_ = record;
    }
    if (!done.ok()) {
      if (settings_.save_costmap_on_failure && planned_on != nullptr && !planned_on->costmap().cells.empty()) {
        ReplayJob job;
        job.prefix = "eaci_failed_plan";
        job.params = params;
        job.algorithm = options.algorithm;
        job.request = record;
        job.notes = replayNotes("the costmap of a failed plan", config);
        job.costmap = planned_on->costmap();  // as planned on: a start in the band opened
        if (!writer_->submit(std::move(job))) say(LogLevel::kWarn, "could not hand the failed plan's costmap to the writer");
      }
    }
    return done;
  };
  bool changes_read = false;
  const auto failure = [&](PlanOutcome outcome, const std::string& why) -> PlanReply {
    if (!changes_read) source_.changesNotRead();
    reply.outcome = outcome;
    reply.error = why;
    return finish(reply);
  };
  const auto stop_outcome = [&] { return stoppedOutcome(static_cast<StopReason>(stop_reason.load())); };

  const eaci::MapFrame& frame = costmap.frame;
  if (const std::string problem = costmapProblem(costmap); !problem.empty())
    return failure(PlanOutcome::kBadCostmap, problem);
  if (const std::string invalid = eaci::validationError(params); !invalid.empty())
    return failure(PlanOutcome::kBadParameters, "invalid parameter: " + invalid);
  eaci::CellInterpretation interpretation =
      eaci::CellInterpretation::costmap(static_cast<std::uint8_t>(params.lethal_cost), params.allow_unknown);
  interpretation.unknown_value = kCostmapUnknown;

  // The planner's copy of the costmap, brought up to it where it changed; or, for a costmap
  // costmap_2d has emptied by a resize, the last filled one placed into its frame.
  const CostmapSource::Read read = source_.read(costmap, changes, interpretation, params.allow_corner_cutting,
                                                eaci::costRule(params), rolling_, Clock::now());
  changes_read = true;
  CostmapMirror& mirror = *read.mirror;
  planned_on = &mirror;
  reply.stood_in_for_emptied = read.stood_in;
  reply.phases.afresh = read.synced.afresh;
  reply.phases.rows_read = read.synced.rows_read;
  reply.phases.rows_changed = read.synced.rows_changed;
  phaseDone(reply.phases.costmap);

  const auto start_cell = frame.worldToCell(request.start);
  if (!start_cell) return failure(PlanOutcome::kStartOffMap, "start " + where(request.start) + " is off the costmap");
  const auto goal_cell = frame.worldToCell(request.goal);
  if (!goal_cell) return failure(PlanOutcome::kGoalOffMap, "goal " + where(request.goal) + " is off the costmap");
  const StartCellCheck start_check = openStartCell(mirror.costmap(), interpretation, *start_cell, should_stop);
  if (!start_check.ok)
    return failure(start_check.stopped ? stop_outcome() : start_check.outcome,
                   "start " + where(request.start) + ": " + start_check.error);
  for (const eaci::Cell& cell : start_check.opened) mirror.open(cell, start_check.opened_cost);  // until the next sync
  reply.start_cells_opened = start_check.cells_opened;
  if (start_check.cells_opened > 0)
    say(LogLevel::kInfo, "start " + where(request.start) + " is in the inflated band (cost " +
                             std::to_string(start_check.start_cost) + ", lethal_cost " +
                             std::to_string(params.lethal_cost) + "): planning out of it by the cheapest way (" +
                             std::to_string(start_check.cells_opened) + " cells), as navfn plans from the robot's cell");

  phaseDone(reply.phases.start);
  const eaci::GridView view = mirror.view();
  const bool goal_free = view.isFree(*goal_cell);
  // The goal tolerance, as navfn's: the route ends on the cell nearest to the goal, within the
  // tolerance, that the start can reach. First the nearest free cell (the goal itself when it is
  // free: no extra work in the normal case); only when no route reaches it, a flood from the
  // start finds the nearest reachable cell (a free cell behind a wall must not win).
  const double radius_cells = tolerance / frame.resolution;
  const auto stopped_while = [&](const std::string& what) {
    return failure(stop_outcome(),
                   std::string(toString(static_cast<StopReason>(stop_reason.load()))) + " while " + what);
  };
  std::optional<eaci::Cell> target = eaci::nearestFreeCell(view, *goal_cell, radius_cells, should_stop);
  if (!target) {
    if (stop_reason.load() != static_cast<int>(StopReason::kNone))
      return stopped_while("looking for a free cell near the goal");
    return failure(PlanOutcome::kGoalBlocked, "goal " + where(request.goal) +
                                                  " is in an obstacle and no free cell lies within " +
                                                  eaci::formatNumber(tolerance) + " m of it");
  }

  phaseDone(reply.phases.goal);

  useLandmarksFor(frame, options.landmarks);
  eaci::PlanOptions plan_options;
  plan_options.record_pheromone = options.visualize_pheromone && request.record_pheromone;
  plan_options.workspace = workspace_.get();
  plan_options.should_stop = [&should_stop](int) { return should_stop(); };
  plan_options.never_worse_than_search = true;  // a lucky ant's detour never reaches the robot
  // With turn_cost > 0 the turn onto the goal's heading is priced too (grid angles are the
  // costmap frame's yaws, y up the rows); the robot's own heading is not (docs/ros.md).
  plan_options.end_headings.goal = eaci::travelHeading(request.goal_yaw, options.orientation_mode);
  // The planners' grid, kept in the mirror: both plans of a goal tolerance and the flood between them search it.
  const eaci::CostGrid& grid = mirror.grid();
  reply.result = eaci::plan(grid, *start_cell, *target, options.algorithm, params, plan_options);
  reply.phases.core = reply.result.times;
  phase_start = Clock::now();
  if (reply.result.status == eaci::PlanStatus::kNoPath && !reply.result.interrupted && radius_cells >= 1) {
    const auto reachable = eaci::nearestReachableCell(grid, *start_cell, *goal_cell, radius_cells, should_stop);
    if (stop_reason.load() != static_cast<int>(StopReason::kNone))
      return stopped_while("looking for a cell near the goal that the start can reach");
    if (!reachable)
      return failure(goal_free ? PlanOutcome::kNoPath : PlanOutcome::kGoalBlocked,
                     "goal " + where(request.goal) + " cannot be reached from the start, nor any cell within " +
                         eaci::formatNumber(tolerance) + " m of it");
    if (!(*reachable == *target)) {  // else the plan failed for another reason: its error stands
      say(LogLevel::kInfo, "no route reaches " + where(frame.cellToWorld(*target)) + ": planning to " +
                               where(frame.cellToWorld(*reachable)) +
                               ", the cell nearest the goal within the tolerance that the start can reach");
      target = reachable;
      reply.result = eaci::plan(grid, *start_cell, *target, options.algorithm, params, plan_options);
    }
  }
  phaseDone(reply.phases.tolerance);
  reportLandmarks(frame);
  if (reply.result.interrupted) reply.stopped_by = static_cast<StopReason>(stop_reason.load());
  if (!reply.result.success()) {
    if (reply.result.status != eaci::PlanStatus::kStopped)
      return failure(outcomeOf(reply.result.status, goal_free), reply.result.error);
    if (reply.stopped_by == StopReason::kTimeLimit)
      return failure(PlanOutcome::kTimeLimit, "no route found within max_planning_time (" +
                                                  eaci::formatNumber(options.max_planning_time) + " s)");
    return failure(stoppedOutcome(reply.stopped_by), std::string(toString(reply.stopped_by)) + " after " +
                                                         std::to_string(reply.result.iterations_run) +
                                                         " iterations, before a route was found");
  }
  const std::string defect = routeDefect(view, reply.result.path, *start_cell, *target, params.allow_corner_cutting);
  if (!defect.empty())
    return failure(PlanOutcome::kInternalError, "internal error: the planner's route is not drivable (" + defect + "); no plan");
  if (!(*target == *goal_cell)) reply.goal = frame.cellToWorld(*target);
  // What goes out: the smoothed route's poses, every segment between two of them checked; if
  // the smoother got one wrong, the grid route's (just checked cell by cell).
  if (settings_.smoothed_path_hook) settings_.smoothed_path_hook(reply.result.smoothed_path);
  const FinishedRoute finished = finishRoute(view, frame, reply.result.smoothed_path, reply.result.path, request.start,
                                             reply.goal, params.allow_corner_cutting, settings_.poses_hook);
  phaseDone(reply.phases.finish);
  if (finished.poses.empty())
    return failure(PlanOutcome::kInternalError, "internal error: no route's poses pass the last check (" +
                                                    finished.defect + "); no plan");
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
  reply.outcome = PlanOutcome::kOk;
  return finish(reply);
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
