// A landmark maker (LandmarkCache::Maker) that blocks until the test releases it, and a check
// that something a plan does returns while the maker is still blocked (issue #27: no plan waits
// for the landmark thread). No timed bound on the plan: the maker is held until the check is
// over, so a plan that waited for it would never return; the bound below only guards against
// that hang, and on a hang the maker is released (so that the waiting thread, and whatever it
// owns, ends before the test does).
#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "eaci/search/landmark_cache.hpp"
#include "eaci/search/landmarks.hpp"

namespace eaci_test {

class LandmarkGate {
 public:
  // The maker: counts its calls, blocks until release(), notes whether it was cancelled by
  // then, and makes the landmarks (Landmarks::compute) unless it was. It owns the gate (a
  // shared_ptr), so it may outlive the test's references to it.
  static eaci::LandmarkCache::Maker maker(const std::shared_ptr<LandmarkGate>& gate) {
    return [gate](const eaci::CostGrid& grid, int count, const std::atomic<bool>* cancel) {
      {
        std::unique_lock<std::mutex> lock(gate->mutex_);
        ++gate->entered_;
        gate->changed_.notify_all();
        gate->changed_.wait(lock, [&] { return gate->released_; });
      }
      const bool cancelled = cancel != nullptr && cancel->load();
      auto made = cancelled ? nullptr : eaci::Landmarks::compute(grid, count, cancel);
      std::lock_guard<std::mutex> lock(gate->mutex_);
      ++gate->left_;
      gate->cancelled_ += cancelled ? 1 : 0;
      gate->changed_.notify_all();
      return made;
    };
  }

  // Blocks until release(), counted as a call that entered and, once released, left: for a
  // thread that ends late after its job (a ThreadStarter's thread, as a nice-19 thread on a
  // loaded machine is late to end).
  void hold() {
    std::unique_lock<std::mutex> lock(mutex_);
    ++entered_;
    changed_.notify_all();
    changed_.wait(lock, [&] { return released_; });
    ++left_;
    changed_.notify_all();
  }

  void release() {
    std::lock_guard<std::mutex> lock(mutex_);
    released_ = true;
    changed_.notify_all();
  }
  bool released() {
    std::lock_guard<std::mutex> lock(mutex_);
    return released_;
  }
  // Waits (a minute at most: a hang guard) until the maker was called `count` times / returned
  // `count` times.
  bool waitEntered(int count) { return waitFor([&] { return entered_ >= count; }); }
  bool waitLeft(int count) { return waitFor([&] { return left_ >= count; }); }
  // Waits (as above) until `count` calls have returned having seen their cancel flag set: a
  // released call counts only once its thread has run again, which on a loaded machine may be
  // after the test's next step.
  bool waitCancelled(int count) { return waitFor([&] { return cancelled_ >= count; }); }
  int entered() {
    std::lock_guard<std::mutex> lock(mutex_);
    return entered_;
  }
  int left() {
    std::lock_guard<std::mutex> lock(mutex_);
    return left_;
  }
  // Calls that saw their cancel flag set when they were released.
  int cancelled() {
    std::lock_guard<std::mutex> lock(mutex_);
    return cancelled_;
  }

 private:
  template <class Done>
  bool waitFor(Done done) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, std::chrono::minutes(1), done);
  }

  std::mutex mutex_;
  std::condition_variable changed_;
  bool released_ = false;
  int entered_ = 0, left_ = 0, cancelled_ = 0;
};

// Runs `step` (which owns what it uses) on a thread of its own and checks that it returns while
// `gate`'s maker is still blocked. The gate is held throughout, so a step that waited for the
// maker would not return at all; kHangGuard only turns that hang into a failure here (the gate
// is then released and the step waited for, so nothing outlives the test).
inline ::testing::AssertionResult returnsWhileTheMakerIsBlocked(const std::shared_ptr<LandmarkGate>& gate,
                                                                std::function<void()> step) {
  constexpr auto kHangGuard = std::chrono::seconds(20);
  if (gate->released()) return ::testing::AssertionFailure() << "the gate was released before the step";
  auto done = std::make_shared<std::promise<void>>();
  std::future<void> returned = done->get_future();
  std::thread([step = std::move(step), done]() mutable {
    step();
    step = nullptr;  // what it owns goes before the test is told
    done->set_value();
  }).detach();
  if (returned.wait_for(kHangGuard) == std::future_status::ready) {
    if (gate->released()) return ::testing::AssertionFailure() << "the gate was released during the step";
    return ::testing::AssertionSuccess();
  }
  gate->release();
  returned.wait();
  return ::testing::AssertionFailure() << "it did not return while the landmark maker was blocked (it waited for it)";
}

}  // namespace eaci_test
