// Landmarks kept for a planner that plans again and again (LandmarkCache), made in a thread of
// their own at the lowest priority, which no plan ever waits for.
#pragma once

#include <atomic>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include "eaci/grid/cost_grid.hpp"
#include "eaci/parallel/worker_group.hpp"
#include "eaci/search/landmarks.hpp"

namespace eaci {

// Landmarks kept for a planner that plans again and again, made in the background: the first
// plan on a costmap asks, finds none, and starts a thread that makes them; later plans on that
// costmap, or on one no cell of which is cheaper, use them. When the costmap gets cheaper
// somewhere (an obstacle cleared), new ones are made on the cell-wise cheapest of the old and
// the new costmap, so that they hold for both, and costmaps that come and go between the two
// do not make them again each time. Plans that find none ready search with octile bounds alone:
// the same costs, though among equally cheap routes they may pick another.
//
// No plan waits for the landmark thread (issue #27). move_base holds its costmap lock across a
// whole plan, and the thread runs at nice 19: on a loaded machine it may not run for seconds, so
// joining it (to start the next one, or in a destructor a plan runs) held the robot's costmap
// that long. Design: every making is a *job*, a detached thread that owns everything it touches
// through shared pointers: the cache's State (mutex, the landmarks ready, the job whose
// landmarks are wanted, the error text), its own Job (the cancel flag), a copy of the grid, and
// a copy of the Maker. It never touches the LandmarkCache. When it ends it stores its landmarks
// in the State only if it is still the State's job and was not cancelled; otherwise its work is
// dropped. The cache's destructor and a change of map size only set the job's cancel flag (the
// destructor then drops its reference to the State: the last owner, the job if it outlives the
// cache, frees it); MeetingSearch::useLandmarks and the service's workspace reset destroy the
// cache, so they wait for nothing either. Nothing joins a thread, and the plan side never blocks
// on the State's mutex: usableFor only tries it (a job holds it for a few pointer moves when it
// ends; the plan then answers "none yet"). Several jobs may run at once for a while (a cancelled
// one that has not yet seen its flag, and the next one); each makes only its own. A
// ThreadStarter (tests) returns the std::thread it started: it is detached too. The process
// may end while a job runs: it touches nothing static and nothing of the cache, only what it owns.
//
// Maps whose size keeps changing (gmapping grows its map every few seconds): tables for a size
// that will be gone before any plan uses them are not started, adaptively. A table is *wasted*
// when the map's size (width, height, move and cost rule) changes before any plan was given
// it (cancelled in flight, or made and dropped unused). After w tables wasted in a row, a new
// size must be seen on min(1 + w, max_settle_asks) asks in a row (usableFor is asked once a
// plan) before a table is started for it; a table a plan uses sets w back to 0. So a static
// map, or one that keeps its size long enough for its tables to be used, gets them from the
// first plan on a size, as without a policy; a map that changes size on every plan or two
// wastes one or two tables and then starts none until its size holds still. A change of size
// cancels the job in flight (a flag: without waiting) and drops the tables of the old size
// (they never hold on another). Measured in docs/robustness.md ("Landmarks on maps that grow").
//
// Nothing here reaches the plan as an exception: a failure while making them (std::bad_alloc,
// anything) or a thread that cannot start leaves the cache without new landmarks, says why
// (lastError()), and the next plan that asks tries again.
class LandmarkCache {
 public:
  // Makes landmarks (Landmarks::compute); replaceable for tests that make it fail or block. It
  // runs on the job's detached thread, as a copy owned by the job, possibly after the cache is
  // gone: it must own (or outlive) what it uses, and should return soon once `cancel` is true.
  using Maker = std::function<std::shared_ptr<const Landmarks>(const CostGrid&, int count, const std::atomic<bool>* cancel)>;

  // The most asks in a row on a new size before tables for it are started, after tables
  // were wasted (see the class comment).
  static constexpr int kMaxSettleAsks = 4;

  // `count` landmarks asked for (cut to landmarksThatFit for each map). `make`, `start`: how
  // they are made and their thread started (empty: Landmarks::compute, std::thread); the
  // thread is detached. `max_settle_asks`: kMaxSettleAsks of the size policy (1: no policy, a
  // table for every size at once).
  explicit LandmarkCache(int count, Maker make = {}, ThreadStarter start = {}, int max_settle_asks = kMaxSettleAsks)
      : count_(count), max_settle_asks_(max_settle_asks < 1 ? 1 : max_settle_asks), make_(std::move(make)),
        start_(std::move(start)), state_(std::make_shared<State>()), count_in_use_(count) {}
  LandmarkCache(const LandmarkCache&) = delete;
  LandmarkCache& operator=(const LandmarkCache&) = delete;
  // Cancels the job in flight and lets it go: waits for nothing, not even the State's mutex.
  ~LandmarkCache() {
    if (job_) job_->cancel.store(true, std::memory_order_relaxed);
  }

  // The count asked for.
  int count() const { return count_; }
  // The count it makes (or made) for the last map it was asked about: count() cut to what
  // fits in kMaxLandmarkBytes on that map (landmarksThatFit); count() before any.
  int countInUse() const { return count_in_use_.load(std::memory_order_relaxed); }
  // Why the last attempt to make landmarks failed ("" if it did not). Takes the mutex a job
  // holds for a few pointer moves when it ends.
  std::string lastError() const {
    std::lock_guard<std::mutex> lock(state_->mutex);
    return state_->fixed_error != nullptr ? std::string(state_->fixed_error) : state_->last_error;
  }
  // Jobs this cache started, and jobs that stored their landmarks (for measurements and tests).
  int jobsStarted() const { return started_.load(std::memory_order_relaxed); }
  int jobsFinished() const {
    std::lock_guard<std::mutex> lock(state_->mutex);
    return state_->finished;
  }

  // Landmarks whose bounds hold on `grid`, or null (then making them is under way, or the map's
  // size is not settled yet (the size policy), or none fit on this map, or they could not be made: see
  // lastError()). Never waits for a landmark thread: it only tries the mutex a job takes for a
  // few pointer moves when it ends, and answers null if that job holds it this instant.
  // One plan at a time (the plan's thread owns the size policy's fields).
  std::shared_ptr<const Landmarks> usableFor(const CostGrid& grid) {
    const int in_use = landmarksThatFit(grid.cellCount(), count_);
    count_in_use_.store(in_use, std::memory_order_relaxed);
    // The size policy: a new size cancels the job in flight (a flag: no lock, no wait); a table
    // no plan was given by then was wasted.
    const GridShape shape = GridShape::of(grid);
    if (!seen_ || !(shape == last_shape_)) {
      if (seen_ && job_) job_->cancel.store(true, std::memory_order_relaxed);
      if (unused_) ++wasted_in_a_row_;
      unused_ = false;
      asks_in_a_row_ = 1;
      seen_ = true;
      last_shape_ = shape;
    } else {
      asks_in_a_row_ = std::min(asks_in_a_row_ + 1, max_settle_asks_);
    }
    const int settle_asks = std::min(1 + wasted_in_a_row_, max_settle_asks_);
    std::shared_ptr<const Landmarks> dropped;  // freed after the lock is released
    std::unique_lock<std::mutex> lock(state_->mutex, std::try_to_lock);
    if (!lock.owns_lock()) return nullptr;  // a job is storing its landmarks this instant
    State& s = *state_;
    if (s.ready && !(GridShape::of(s.ready->grid()) == shape)) dropped = std::move(s.ready);  // they never hold again
    if (s.ready && holdsOn(*s.ready, s.finished, grid)) {
      unused_ = false;
      wasted_in_a_row_ = 0;
      return s.ready;
    }
    if (s.job && s.job->cancel.load(std::memory_order_relaxed)) s.job.reset();  // let go
    if (s.job || in_use == 0 || asks_in_a_row_ < settle_asks) return nullptr;
    // The floor is made on the job's thread too, from a copy of the grid and the landmarks
    // held: the plan that asked waits for neither.
    try {
      auto job = std::make_shared<Job>();
      std::function<void()> body = [state = state_, job, floor = grid, held = s.ready, count = in_use,
                                    make = make_]() mutable {
        run(*state, job, std::move(floor), std::move(held), count, make);
      };
      std::thread thread = start_ ? start_(std::move(body)) : std::thread(std::move(body));
      if (thread.joinable()) thread.detach();
      s.job = job;
      job_ = std::move(job);
      unused_ = true;
      started_.fetch_add(1, std::memory_order_relaxed);
      s.last_error.clear();
      s.fixed_error = nullptr;
    } catch (const std::exception& e) {  // no thread (std::system_error), no memory for the copy
      setError(s, "could not start making landmarks: ", e.what());
    } catch (...) {
      setError(s, "could not start making landmarks: an unknown exception", "");
    }
    return nullptr;
  }

 private:
  struct Job {
    std::atomic<bool> cancel{false};
  };
  // What the cache shares with its jobs; the last owner frees it.
  struct State {
    std::mutex mutex;
    std::shared_ptr<const Landmarks> ready;  // under mutex
    std::shared_ptr<Job> job;                // under mutex: the job in flight, whose landmarks are wanted
    std::string last_error;                  // under mutex
    const char* fixed_error = nullptr;       // under mutex: instead of last_error when its text could not be made
    int finished = 0;                        // under mutex
  };

  // When the error's text cannot be made (no memory for the string: its handler is where memory
  // ran out), this fixed one is said instead.
  static constexpr const char* kErrorWithoutText =
      "making landmarks failed, and there was no memory left to say why (std::bad_alloc)";

  // `prefix` + `what` into `text`, and null; or `text` empty and kErrorWithoutText when that
  // cannot be allocated. Never throws (it runs in catch handlers, also on the job's thread).
  static const char* errorText(std::string& text, const char* prefix, const char* what) noexcept {
    try {
      text = prefix;
      text += what;
      return nullptr;
    } catch (...) {
      text.clear();
      return kErrorWithoutText;
    }
  }
  // The same as the state's error; the caller holds the mutex.
  static void setError(State& state, const char* prefix, const char* what) noexcept {
    state.fixed_error = errorText(state.last_error, prefix, what);
  }

  // The job's body, on its detached thread: touches only what it owns. Catches everything (an
  // exception leaving a thread would end the process), its own error path included: the text of
  // an error is made without throwing (an allocation failure there gives kErrorWithoutText); a
  // failure leaves the landmarks held as they were.
  static void run(State& state, const std::shared_ptr<Job>& job, CostGrid floor, std::shared_ptr<const Landmarks> held,
                  int count, const Maker& make) {
    yieldToPlans();
    std::shared_ptr<const Landmarks> made;
    std::string error;
    const char* fixed_error = nullptr;  // kErrorWithoutText when `error` could not be made
    try {
      if (held && Landmarks::sameShape(held->grid(), floor)) cheapestOf(held->grid(), floor, &job->cancel);
      held.reset();
      if (!job->cancel.load(std::memory_order_relaxed))
        made = make ? make(floor, count, &job->cancel) : Landmarks::compute(floor, count, &job->cancel);
    } catch (const std::exception& e) {
      fixed_error = errorText(error, "making landmarks failed: ", e.what());
    } catch (...) {
      fixed_error = errorText(error, "making landmarks failed with an unknown exception", "");
    }
    std::shared_ptr<const Landmarks> replaced;  // freed after the lock is released
    std::lock_guard<std::mutex> done(state.mutex);
    if (state.job != job) return;  // superseded: its work is dropped
    state.job.reset();
    if (job->cancel.load(std::memory_order_relaxed)) return;  // cancelled (a new size, the cache gone)
    if (made) {
      replaced = std::move(state.ready);
      state.ready = std::move(made);
      ++state.finished;
    }
    state.last_error.swap(error);  // no allocation under the lock
    state.fixed_error = fixed_error;
  }

  // Whether `ready` (the landmarks the `finished`-th job stored) hold on `grid`: every row
  // checked when either is new to the cache, then only the rows `grid` changed since (its
  // rowChange numbers): on a grid kept from plan to plan and changed in a few rows, a check
  // costs those rows and one number per row, not a pass over every cell.
  bool holdsOn(const Landmarks& ready, int finished, const CostGrid& grid) {
    if (!Landmarks::sameShape(grid, ready.grid())) return false;
    const auto rows = static_cast<std::size_t>(grid.height());
    const bool known = checked_job_ == finished && checked_grid_ == grid.identity() && checked_rows_.size() == rows;
    if (!known) {
      checked_rows_.assign(rows, 0);
      cheaper_in_row_.assign(rows, 0);
      cheaper_rows_ = 0;
    }
    for (std::size_t r = 0; r < rows; ++r) {
      const std::uint64_t change = grid.rowChange(static_cast<int>(r));
      if (known && checked_rows_[r] == change) continue;
      const std::uint8_t cheaper = ready.cheaperRow(grid, static_cast<int>(r)) ? 1 : 0;
      cheaper_rows_ += static_cast<std::size_t>(cheaper) - static_cast<std::size_t>(cheaper_in_row_[r]);
      cheaper_in_row_[r] = cheaper;
      checked_rows_[r] = change;
    }
    checked_job_ = finished;
    checked_grid_ = grid.identity();
    return cheaper_rows_ == 0;
  }

  // The landmarks are made beside the plans that need them now: on a machine with few cores
  // their thread would take a core from a plan and push it past its time limit, so it runs at
  // the lowest priority (Linux: a thread's own nice value; elsewhere as it is).
  static void yieldToPlans() {
#ifdef __linux__
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
  }

  // Each cell of `into` at most as costly as in `other` (an obstacle is the costliest); stops
  // early (leaving `into` part made) once `cancel` is true, asked every kCancelPollCells cells.
  static void cheapestOf(const CostGrid& other, CostGrid& into, const std::atomic<bool>* cancel) {
    forCellChunks(into.cellCount(), cancel, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const std::uint8_t was = other.cellBytes()[i];
        if (was < into.cellBytes()[i]) into.setCost(into.cellAt(i), was);  // `was` is a cost, not an obstacle
      }
    });
  }

  const int count_;
  const int max_settle_asks_;
  const Maker make_;
  const ThreadStarter start_;
  const std::shared_ptr<State> state_;
  std::atomic<int> count_in_use_;     // countInUse
  std::atomic<int> started_{0};       // jobsStarted
  // The plan's (usableFor, one plan at a time): the job it started last, to cancel; the size policy.
  std::shared_ptr<Job> job_;
  bool seen_ = false;
  GridShape last_shape_;
  int asks_in_a_row_ = 0;    // on last_shape_, counted up to max_settle_asks_
  bool unused_ = false;      // a table was started and no plan has been given one since
  int wasted_in_a_row_ = 0;  // tables started that no plan was given before the size changed
  // The plan's: what holdsOn knows of the landmarks of job checked_job_ on grid checked_grid_.
  int checked_job_ = -1;
  std::uint64_t checked_grid_ = 0;
  std::vector<std::uint64_t> checked_rows_;  // per row: the rowChange number it was checked at
  std::vector<std::uint8_t> cheaper_in_row_; // per row: some cell cheaper than the landmarks' grid
  std::size_t cheaper_rows_ = 0;
};

}  // namespace eaci
