// Landmarks kept for a planner that plans again and again (LandmarkCache), made in a thread of
// their own at the lowest priority.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

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
// Nothing here reaches the plan as an exception: a failure while making them (std::bad_alloc,
// anything) or a thread that cannot start leaves the cache without new landmarks, says why
// (lastError()), and the next plan that asks tries again.
class LandmarkCache {
 public:
  // Makes landmarks (Landmarks::compute); replaceable for tests that make it fail.
  using Maker = std::function<std::shared_ptr<const Landmarks>(const CostGrid&, int count, const std::atomic<bool>* cancel)>;

  // `count` landmarks asked for (cut to landmarksThatFit for each map). `make`, `start`: how
  // they are made and their thread started (empty: Landmarks::compute, std::thread).
  explicit LandmarkCache(int count, Maker make = {}, ThreadStarter start = {})
      : count_(count), make_(std::move(make)), start_(std::move(start)) {}
  LandmarkCache(const LandmarkCache&) = delete;
  LandmarkCache& operator=(const LandmarkCache&) = delete;
  ~LandmarkCache() {
    cancel_.store(true);
    if (worker_.joinable()) worker_.join();
  }

  // The count asked for.
  int count() const { return count_; }
  // The count it makes (or made) for the last map it was asked about: count() cut to what
  // fits in kMaxLandmarkBytes on that map (landmarksThatFit); count() before any.
  int countInUse() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return count_in_use_;
  }
  // Why the last attempt to make landmarks failed ("" if it did not).
  std::string lastError() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_error_;
  }

  // Landmarks whose bounds hold on `grid`, or null (then making them is under way, or none
  // fit on this map, or they could not be made: see lastError()).
  std::shared_ptr<const Landmarks> usableFor(const CostGrid& grid) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (ready_ && ready_->holdsFor(grid)) return ready_;
    count_in_use_ = landmarksThatFit(grid.cellCount(), count_);
    if (computing_ || count_in_use_ == 0) return nullptr;
    if (worker_.joinable()) worker_.join();  // finished: it cleared computing_
    // The floor is made on the worker thread too, from a copy of the grid and the landmarks
    // held: the plan that asked waits for neither.
    std::shared_ptr<const Landmarks> held = ready_;
    try {
      std::function<void()> body = [this, floor = grid, held, count = count_in_use_]() mutable {
        make(std::move(floor), held, count);
      };
      worker_ = start_ ? start_(std::move(body)) : std::thread(std::move(body));
      computing_ = true;
      last_error_.clear();
    } catch (const std::exception& e) {  // no thread (std::system_error), no memory for the copy
      last_error_ = std::string("could not start making landmarks: ") + e.what();
    }
    return nullptr;
  }

 private:
  // The worker thread's body: catches everything (an exception leaving a thread would end the
  // process); a failure leaves the landmarks held as they were.
  void make(CostGrid floor, const std::shared_ptr<const Landmarks>& held, int count) {
    yieldToPlans();
    std::shared_ptr<const Landmarks> made;
    std::string error;
    try {
      if (held && Landmarks::sameShape(held->grid(), floor)) cheapestOf(held->grid(), floor);
      made = make_ ? make_(floor, count, &cancel_) : Landmarks::compute(floor, count, &cancel_);
    } catch (const std::exception& e) {
      error = std::string("making landmarks failed: ") + e.what();
    } catch (...) {
      error = "making landmarks failed with an unknown exception";
    }
    std::lock_guard<std::mutex> done(mutex_);
    if (made) ready_ = std::move(made);
    last_error_ = error;
    computing_ = false;
  }

  // The landmarks are made beside the plans that need them now: on a machine with few cores
  // their thread would take a core from a plan and push it past its time limit, so it runs at
  // the lowest priority (Linux: a thread's own nice value; elsewhere as it is).
  static void yieldToPlans() {
#ifdef __linux__
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
  }

  // Each cell of `into` at most as costly as in `other` (an obstacle is the costliest).
  static void cheapestOf(const CostGrid& other, CostGrid& into) {
    for (std::size_t i = 0; i < into.cellCount(); ++i) {
      const std::uint8_t was = other.cellBytes()[i];
      if (was < into.cellBytes()[i]) into.setCost(into.cellAt(i), was);  // `was` is a cost, not an obstacle
    }
  }

  const int count_;
  const Maker make_;
  const ThreadStarter start_;
  mutable std::mutex mutex_;
  std::shared_ptr<const Landmarks> ready_;  // under mutex_
  bool computing_ = false;                  // under mutex_
  int count_in_use_ = count_;               // under mutex_
  std::string last_error_;                  // under mutex_
  std::thread worker_;
  std::atomic<bool> cancel_{false};
};

}  // namespace eaci
