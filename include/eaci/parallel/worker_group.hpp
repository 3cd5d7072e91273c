// A fixed set of threads, started once, that run the same job on demand: the colony walks
// each iteration's ants on it instead of starting threads every iteration, and the search that
// meets in the middle runs its two sides on it, round by round.
//
// Jobs come in quick succession there (a round every 0.1-0.2 ms), and waking a sleeping thread
// costs about as much: a thread that finds nothing to do, and the caller waiting for the
// others, first watch for up to kSpin before they go to sleep. On a busy machine (move_base's
// own threads, a simulation) a worker may still wake late: share() does not wait for it.
//
// Nothing here ends the process: an exception a job throws, on any thread, reaches the caller
// of run()/share() (the first one, rethrown there), and a thread that cannot be started
// (std::system_error, e.g. a thread limit, or std::bad_alloc) leaves the group with the threads it did start
// (workers(); at least the caller's), so the work runs on fewer threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace eaci {

// Starts a thread running `body` (std::thread's constructor: throws std::system_error when it
// cannot). Replaceable for tests that make thread starts fail.
using ThreadStarter = std::function<std::thread(std::function<void()> body)>;

// Destroys `owned` on a detached thread of its own, which owns it and touches nothing else:
// for what a plan lets go whose destructor joins threads (a WorkerGroup, a workspace holding
// some), which a loaded machine may schedule late, so that the plan does not wait for them.
// When no thread can be started it is destroyed here, as before.
template <class T>
void destroyOffThisThread(std::unique_ptr<T> owned) {
  if (!owned) return;
  try {
    // The box is shared with the thread, which empties it; our reference never destroys `owned`
    // once the thread started (its copy outlives the reset), and keeps it when it did not.
    auto box = std::make_shared<std::unique_ptr<T>>(std::move(owned));
    try {
      std::thread([box]() { box->reset(); }).detach();
    } catch (const std::exception&) {  // no thread (std::system_error) or no memory for its state
      box->reset();
    }
  } catch (const std::exception&) {  // no memory for the box: `owned` is still ours
    owned.reset();
  }
}

class WorkerGroup {
 public:
  using Job = std::function<void(int worker)>;

  // `workers` threads in all, the calling thread included (so workers - 1 are started; fewer
  // when a start fails, see workers()). `start`: how a thread is started (empty: std::thread).
  explicit WorkerGroup(int workers, const ThreadStarter& start = {}) {
    threads_.reserve(static_cast<std::size_t>(std::max(0, workers - 1)));
    for (int w = 1; w < workers; ++w) {
      try {
        std::function<void()> body = [this, w] { serve(w); };
        threads_.push_back(start ? start(std::move(body)) : std::thread(std::move(body)));
      } catch (const std::exception&) {  // std::system_error (no thread), std::bad_alloc (its state)
        break;  // no more threads: the group works on those it has
      }
    }
  }
  // The workers the group has, the calling thread included: run() calls job(w) for w in
  // [0, workers()).
  int workers() const { return static_cast<int>(threads_.size()) + 1; }
  WorkerGroup(const WorkerGroup&) = delete;
  WorkerGroup& operator=(const WorkerGroup&) = delete;
  ~WorkerGroup() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_.store(true, std::memory_order_release);
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }

  // Calls job(w) once for every worker w in [0, workers), worker 0 on the calling thread, and
  // returns when all have returned; rethrows the first exception a worker threw.
  void run(const Job& job) { start(job, true); }

  // Calls job(0) on the calling thread and job(w) on each worker w that wakes before the
  // calling thread has returned from it; returns when every call has returned (rethrowing the
  // first exception). For jobs whose parts go to whoever claims them first (an atomic counter):
  // a worker that wakes late then leaves its parts to the others instead of holding them up.
  void share(const Job& job) { start(job, false); }

 private:
  static constexpr std::chrono::microseconds kSpin{50};

  // Watches `ready` for up to kSpin; true once it holds.
  template <class Ready>
  static bool spinUntil(const Ready& ready) {
    const auto until = std::chrono::steady_clock::now() + kSpin;
    for (int k = 1;; ++k) {
      if (ready()) return true;
      if (k % 64 == 0 && std::chrono::steady_clock::now() >= until) return false;
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    }
  }

  void start(const Job& job, bool everyone) {
    if (threads_.empty()) {
      job(0);
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &job;
      open_ = true;
      // run(): every worker must take part; share(): only those that join while it is open.
      pending_.store(everyone ? threads_.size() : 0, std::memory_order_relaxed);
      everyone_ = everyone;
      error_ = nullptr;
      generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    runGuarded(job, 0);
    if (!everyone) {
      std::lock_guard<std::mutex> lock(mutex_);
      open_ = false;  // nobody joins from here on
    }
    const auto all_done = [this] { return pending_.load(std::memory_order_acquire) == 0; };
    if (!spinUntil(all_done)) {
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, all_done);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = nullptr;
    if (error_) std::rethrow_exception(error_);
  }

  void serve(int worker) {
    std::uint64_t seen = 0;
    for (;;) {
      const auto work_or_stop = [&] {
        return stopping_.load(std::memory_order_acquire) || generation_.load(std::memory_order_acquire) != seen;
      };
      if (!spinUntil(work_or_stop)) {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, work_or_stop);
      }
      const Job* job = nullptr;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_.load(std::memory_order_relaxed)) return;
        seen = generation_.load(std::memory_order_relaxed);
        if (!open_) continue;  // a share() that ended before this worker woke
        if (!everyone_) pending_.fetch_add(1, std::memory_order_relaxed);
        job = job_;
      }
      runGuarded(*job, worker);
      if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        std::lock_guard<std::mutex> lock(mutex_);  // the caller checks pending_ under it before it sleeps
        done_.notify_one();
      }
    }
  }

  void runGuarded(const Job& job, int worker) {
    try {
      job(worker);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const Job* job_ = nullptr;       // under mutex_
  bool open_ = false;              // under mutex_: workers may still join the current job
  bool everyone_ = true;           // under mutex_: run() rather than share()
  std::atomic<std::size_t> pending_{0};  // calls on workers not yet returned
  std::atomic<std::uint64_t> generation_{0};
  std::atomic<bool> stopping_{false};
  std::exception_ptr error_;
};

}  // namespace eaci
