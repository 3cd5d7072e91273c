// The planning service when memory runs out: this binary replaces operator new so that the
// N-th allocation after arming throws std::bad_alloc, and fails every allocation site a plan
// reaches in turn (on the planning thread and on the colony's and search's worker threads).
// Each such plan must end as a failed plan with its reason or as a valid route (a failure the
// planner could work around, e.g. landmarks not made), never as a crash or an exception out of
// plan(); and the next plan, with memory back, must give the same route as before.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include "service_test_support.hpp"

namespace {

std::atomic<long> g_countdown{-1};  // < 0: never fail; else fail when it reaches 0
std::atomic<long> g_allocations{0};

void* allocate(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (g_countdown.load(std::memory_order_relaxed) >= 0 && g_countdown.fetch_sub(1) == 0) throw std::bad_alloc();
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void* allocateAligned(std::size_t size, std::size_t alignment) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (g_countdown.load(std::memory_order_relaxed) >= 0 && g_countdown.fetch_sub(1) == 0) throw std::bad_alloc();
  const std::size_t rounded = (size + alignment - 1) / alignment * alignment;
  if (void* p = std::aligned_alloc(alignment, rounded == 0 ? alignment : rounded)) return p;
  throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(std::size_t size, std::align_val_t a) { return allocateAligned(size, static_cast<std::size_t>(a)); }
void* operator new[](std::size_t size, std::align_val_t a) { return allocateAligned(size, static_cast<std::size_t>(a)); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace {

using namespace eaci_service;
using namespace eaci_service::test;

void failEveryAllocationInTurn(eaci::Algorithm algorithm, int threads) {
  PlanningService service(ServiceSettings{}, Logger{});
  PlanningService::Configuration config = configuration(algorithm);
  config.params.threads = threads;
  configure(service, config);
  CostmapSnapshot costmap = openCostmap(24, 16);
  for (int row = 0; row < 12; ++row) at(costmap, row, 12) = kCostmapLethal;
  const PlanRequest r = request(costmap, {2, 2}, {2, 21});
  const PlanReply reference = service.plan(costmap, r);
  ASSERT_TRUE(reference.ok()) << reference.error;

  g_allocations = 0;
  (void)service.plan(costmap, r);
  const long per_plan = g_allocations.load();
  ASSERT_GT(per_plan, 10);
  std::printf("%ld allocations in one plan\n", per_plan);
  int failed = 0;
  for (long n = 0; n < per_plan; ++n) {
    CostmapSnapshot copy = costmap;  // the caller's copy is made before memory runs out
    g_countdown = n;
    const PlanReply reply = service.plan(std::move(copy), r);
    g_countdown = -1;
    if (reply.ok()) {
      EXPECT_EQ(routeDefect(costmap, reply.result.path, {2, 2}, {2, 21}), "") << "allocation " << n;
    } else {
      ++failed;
      EXPECT_EQ(reply.outcome, PlanOutcome::kInternalError) << "allocation " << n << ": " << reply.error;
      // The reason is there unless the failed allocation was the reason's own.
      if (reply.error.empty()) ADD_FAILURE() << "allocation " << n << ": a failed plan without a reason";
    }
    const PlanReply next = service.plan(costmap, r);
    ASSERT_TRUE(next.ok()) << "allocation " << n << ": the next plan failed: " << next.error;
    EXPECT_EQ(next.result.path, reference.result.path) << "allocation " << n;
  }
  EXPECT_GT(failed, 0);
}

// The first plan of a service allocates its workspace, worker threads and buffers too.
void failEveryAllocationOfAFirstPlanInTurn(int threads) {
  CostmapSnapshot costmap = openCostmap(24, 16);
  for (int row = 0; row < 12; ++row) at(costmap, row, 12) = kCostmapLethal;
  const PlanRequest r = request(costmap, {2, 2}, {2, 21});
  PlanningService::Configuration config = configuration();
  config.params.threads = threads;
  long per_plan = 0;
  eaci::CellPath reference;
  {
    PlanningService service(ServiceSettings{}, Logger{});
    configure(service, config);
    CostmapSnapshot copy = costmap;
    g_allocations = 0;
    const PlanReply first = service.plan(std::move(copy), r);
    per_plan = g_allocations.load();
    ASSERT_TRUE(first.ok()) << first.error;
    reference = first.result.path;
  }
  std::printf("%ld allocations in a first plan\n", per_plan);
  for (long n = 0; n < per_plan; ++n) {
    PlanningService service(ServiceSettings{}, Logger{});
    configure(service, config);
    CostmapSnapshot copy = costmap;
    g_countdown = n;
    const PlanReply reply = service.plan(std::move(copy), r);
    g_countdown = -1;
    if (reply.ok()) {
      EXPECT_EQ(routeDefect(costmap, reply.result.path, {2, 2}, {2, 21}), "") << "allocation " << n;
    } else {
      EXPECT_EQ(reply.outcome, PlanOutcome::kInternalError) << "allocation " << n << ": " << reply.error;
      if (reply.error.empty()) ADD_FAILURE() << "allocation " << n << ": a failed plan without a reason";
    }
    const PlanReply next = service.plan(costmap, r);
    ASSERT_TRUE(next.ok()) << "allocation " << n << ": the next plan failed: " << next.error;
    EXPECT_EQ(next.result.path, reference) << "allocation " << n;
  }
}

TEST(PlanningServiceMemory, EveryAllocationOfAFirstPlanCanFail) { failEveryAllocationOfAFirstPlanInTurn(1); }
TEST(PlanningServiceMemory, EveryAllocationOfAFirstThreadedPlanCanFail) { failEveryAllocationOfAFirstPlanInTurn(2); }

TEST(PlanningServiceMemory, EveryAllocationOfAnEaciPlanCanFail) { failEveryAllocationInTurn(eaci::Algorithm::kEaci, 1); }
TEST(PlanningServiceMemory, EveryAllocationOfAThreadedEaciPlanCanFail) {
  failEveryAllocationInTurn(eaci::Algorithm::kEaci, 2);
}
TEST(PlanningServiceMemory, EveryAllocationOfAnAStarPlanCanFail) { failEveryAllocationInTurn(eaci::Algorithm::kAStar, 1); }

TEST(PlanningServiceMemory, AFailedAllocationIsReportedAsOutOfMemory) {
  PlanningService service(ServiceSettings{}, Logger{});
  configure(service, configuration());
  const CostmapSnapshot costmap = openCostmap(24, 16);
  bool named = false;
  for (long n = 0; n < 200 && !named; ++n) {
    CostmapSnapshot copy = costmap;
    const PlanRequest r = request(costmap, {2, 2}, {13, 21});
    g_countdown = n;
    const PlanReply reply = service.plan(std::move(copy), r);
    g_countdown = -1;
    if (reply.outcome != PlanOutcome::kInternalError) continue;
    // The sentence is the behaviour under test here: it says that memory ran out.
    named = reply.error.find("out of memory") != std::string::npos;
  }
  EXPECT_TRUE(named);
}

}  // namespace
