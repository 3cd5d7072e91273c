// The ~cancel service's state, shared by the planner node and the move_base plugin: whether a
// plan is in progress, and the flag the planning service's should_stop reads; every loop of the
// plan that grows with the map (set-up steps, the A* search, the ants' walks) polls should_stop
// every few thousand units of work (eaci::StopPoll), so a cancel stops it within a fraction of a
// millisecond, not only between iterations.
#pragma once

#include <atomic>
#include <mutex>

namespace eaci_service {

class PlanCancellation {
 public:
  // Marks a plan as in progress while it lives; the flag is clear when the plan starts and
  // when it ends, so a cancel never reaches a later plan.
  class Scope {
   public:
    explicit Scope(PlanCancellation& owner) : owner_(owner) { owner_.set(true); }
    ~Scope() { owner_.set(false); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    PlanCancellation& owner_;
  };

  // Asks the plan in progress to stop; false (and nothing happens) when none is in progress.
  bool cancel() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (planning_) cancel_requested_ = true;
    return planning_;
  }

  // For the planning service's should_stop: true once the plan in progress has been cancelled.
  const std::atomic<bool>* flag() const { return &cancel_requested_; }

 private:
  void set(bool planning) {
    std::lock_guard<std::mutex> lock(mutex_);
    planning_ = planning;
    cancel_requested_ = false;
  }

  std::mutex mutex_;
  bool planning_ = false;
  std::atomic<bool> cancel_requested_{false};
};

}  // namespace eaci_service
