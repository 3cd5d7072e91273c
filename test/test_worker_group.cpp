// WorkerGroup: every worker runs the job once per run(), on threads kept between runs, share()
// runs it on the caller and on whoever joins in time, and an exception thrown by a worker reaches the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <functional>
#include <new>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "eaci/parallel/worker_group.hpp"

TEST(PlannerThreads, WorkerGroupRunsEveryWorkerOncePerRunOnKeptThreads) {
  eaci::WorkerGroup group(3);
  std::mutex mutex;
  std::vector<std::set<std::thread::id>> threads_of_worker(3);
  for (int run = 0; run < 50; ++run) {
    std::vector<int> calls(3, 0);
    group.run([&](int worker) {
      std::lock_guard<std::mutex> lock(mutex);
      ++calls[static_cast<std::size_t>(worker)];
      threads_of_worker[static_cast<std::size_t>(worker)].insert(std::this_thread::get_id());
    });
    EXPECT_EQ(calls, std::vector<int>({1, 1, 1})) << "run " << run;
  }
  // Worker 0 is the caller; the others keep their own thread for all 50 runs.
  for (const auto& ids : threads_of_worker) EXPECT_EQ(ids.size(), 1u);
  EXPECT_EQ(*threads_of_worker[0].begin(), std::this_thread::get_id());
  EXPECT_NE(*threads_of_worker[1].begin(), *threads_of_worker[2].begin());
}

TEST(PlannerThreads, WorkerGroupRethrowsAWorkersExceptionAndStaysUsable) {
  eaci::WorkerGroup group(2);
  EXPECT_THROW(group.run([](int worker) {
                 if (worker == 1) throw std::runtime_error("worker 1 failed");
               }),
               std::runtime_error);
  std::atomic<int> calls{0};
  group.run([&](int) { ++calls; });
  EXPECT_EQ(calls.load(), 2);
}

TEST(PlannerThreads, WorkerGroupOfOneRunsOnTheCaller) {
  eaci::WorkerGroup group(1);
  std::thread::id seen;
  group.run([&](int worker) {
    EXPECT_EQ(worker, 0);
    seen = std::this_thread::get_id();
  });
  EXPECT_EQ(seen, std::this_thread::get_id());
}

// share(): parts claimed from a counter are each done exactly once, whoever joins; a worker kept
// busy elsewhere (here: still asleep when the caller is done) holds nothing up, and the group
// stays usable for run() and share() alike.
TEST(PlannerThreads, WorkerGroupShareDoesEveryClaimedPartOnceWhoeverJoins) {
  eaci::WorkerGroup group(3);
  for (int job = 0; job < 200; ++job) {
    const int parts = job % 7;
    std::vector<std::atomic<int>> done(static_cast<std::size_t>(parts));
    std::atomic<int> next{0};
    group.share([&](int) {
      for (int k = next.fetch_add(1); k < parts; k = next.fetch_add(1)) ++done[static_cast<std::size_t>(k)];
    });
    for (int k = 0; k < parts; ++k) EXPECT_EQ(done[static_cast<std::size_t>(k)].load(), 1) << "job " << job;
  }
  std::vector<int> calls(3, 0);
  std::mutex mutex;
  group.run([&](int worker) {
    std::lock_guard<std::mutex> lock(mutex);
    ++calls[static_cast<std::size_t>(worker)];
  });
  EXPECT_EQ(calls, std::vector<int>({1, 1, 1}));
}

TEST(PlannerThreads, WorkerGroupShareRunsOnTheCallerAndRethrows) {
  eaci::WorkerGroup group(2);
  std::atomic<bool> caller_ran{false};
  group.share([&](int worker) {
    if (worker == 0) caller_ran = true;
  });
  EXPECT_TRUE(caller_ran.load());
  EXPECT_THROW(group.share([](int worker) {
                 if (worker == 0) throw std::runtime_error("the caller's part failed");
               }),
               std::runtime_error);
  std::atomic<int> calls{0};
  group.run([&](int) { ++calls; });
  EXPECT_EQ(calls.load(), 2);
}

TEST(PlannerThreads, WorkerGroupWhoseThreadsCannotStartWorksOnThoseItHas) {
  // The second start fails (a thread limit): the group keeps the caller and one thread, and
  // run() and share() work on those, no exception, no std::terminate.
  int starts = 0;
  eaci::WorkerGroup group(4, [&](std::function<void()> body) {
    if (++starts == 2) throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again), "no thread");
    return std::thread(std::move(body));
  });
  EXPECT_EQ(group.workers(), 2);
  std::mutex mutex;
  std::vector<int> calls(2, 0);
  group.run([&](int worker) {
    std::lock_guard<std::mutex> lock(mutex);
    ++calls.at(static_cast<std::size_t>(worker));
  });
  EXPECT_EQ(calls, std::vector<int>({1, 1}));
  std::atomic<int> next{0}, done{0};
  group.share([&](int) {
    for (int k = next.fetch_add(1); k < 100; k = next.fetch_add(1)) done.fetch_add(1);
  });
  EXPECT_EQ(done.load(), 100);
  // No thread at all: the caller alone.
  eaci::WorkerGroup alone(3, [](std::function<void()>) -> std::thread { throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again)); });
  EXPECT_EQ(alone.workers(), 1);
  int ran = 0;
  alone.run([&](int) { ++ran; });
  EXPECT_EQ(ran, 1);
}

TEST(PlannerThreads, WorkerGroupBringsAnExceptionOfAnyThreadToTheCaller) {
  eaci::WorkerGroup group(3);
  for (int thrower = 0; thrower < 3; ++thrower) {
    EXPECT_THROW(group.run([&](int worker) {
                   if (worker == thrower) throw std::bad_alloc();
                 }),
                 std::bad_alloc)
        << "worker " << thrower;
  }
  std::atomic<int> calls{0};
  group.run([&](int) { calls.fetch_add(1); });
  EXPECT_EQ(calls.load(), 3);
}
