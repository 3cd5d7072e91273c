// Asking a caller's stop check from inside a loop without slowing the loop down: a counter of
// the work done, and a call of the check every kWorkBetweenChecks units (cells expanded,
// cells flooded, ant steps, ...). One StopPoll per thread: it is not shared, only the check it
// calls is (a plan's check may be called from every thread the plan uses, at the same time).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <type_traits>

namespace eaci {

// A plan's stop check (PlanOptions::should_stop): called with the number of colony iterations
// done (0 during set-up); true to stop. Must be thread-safe (see planner.hpp).
using StopCheck = std::function<bool(int)>;

class StopPoll {
 public:
  // Units of work between two calls of the check: at 20-50 ns a cell, a call every 0.1-0.2 ms.
  static constexpr std::size_t kWorkBetweenChecks = 4096;

  StopPoll() = default;  // never stops
  // `check` (a StopCheck, a std::function<bool()>, or any callable with (int) or ()) must
  // outlive the poll; an empty std::function never stops. `iteration`: what a StopCheck is
  // called with.
  template <class Check, class = std::enable_if_t<!std::is_same_v<std::decay_t<Check>, StopPoll>>>
  explicit StopPoll(const Check& check, int iteration = 0, std::size_t every = kWorkBetweenChecks)
      : check_(&check), ask_(&askOf<Check>), iteration_(iteration), every_(every == 0 ? 1 : every) {
    if constexpr (std::is_constructible_v<bool, const Check&>)
      if (!static_cast<bool>(check)) ask_ = nullptr;
  }

  // Counts `units` of work; calls the check once kWorkBetweenChecks have added up. True once
  // the check has said stop (and from then on, without calling it again).
  bool tick(std::size_t units = 1) {
    count_ += units;
    if (__builtin_expect(count_ < every_, 1)) return stopped_;
    return askNow();
  }
  // Calls the check now (between set-up steps), unless it has already said stop.
  bool askNow() {
    count_ = 0;
    if (!stopped_ && ask_ != nullptr) stopped_ = ask_(check_, iteration_);
    return stopped_;
  }
  bool stopped() const { return stopped_; }
  // Marks this poll stopped (a poll of another thread said so); never calls the check.
  void latch() { stopped_ = true; }
  bool canStop() const { return ask_ != nullptr; }

  // A poll of the same check for another thread: its own counter, stopped if this one is.
  StopPoll forAnotherThread() const {
    StopPoll other = *this;
    other.count_ = 0;
    return other;
  }

 private:
  template <class Check>
  static bool askOf(const void* check, int iteration) {
    const Check& c = *static_cast<const Check*>(check);
    if constexpr (std::is_invocable_r_v<bool, const Check&, int>) return c(iteration);
    else return c();
  }

  const void* check_ = nullptr;
  bool (*ask_)(const void*, int) = nullptr;
  int iteration_ = 0;
  std::size_t every_ = kWorkBetweenChecks;
  std::size_t count_ = 0;
  bool stopped_ = false;
};

}  // namespace eaci
