// The planning service's own copy of the costmap (CostmapMirror) and the plans on it: brought up
// to date where the costmap changed, told or not; a change anywhere is seen by the next plan, and
// every plan is the plan a fresh grid of the costmap as it is gives, seed for seed.
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "costmap_mirror.hpp"
#include "service_test_support.hpp"

namespace eaci_service {
namespace {

// Random costmap_2d costs, bottom row first: free, graded, inscribed, lethal and unknown cells.
CostmapSnapshot randomCostmap(int width, int height, std::mt19937& random) {
  CostmapSnapshot costmap = test::openCostmap(width, height);
  costmap.order = eaci::RowOrder::kBottomFirst;
  std::uniform_int_distribution<int> value(0, 255);
  for (std::uint8_t& cell : costmap.cells) cell = static_cast<std::uint8_t>(value(random));
  return costmap;
}

eaci::CellInterpretation costmapInterpretation() {
  eaci::CellInterpretation interpretation = eaci::CellInterpretation::costmap(253, true);
  interpretation.unknown_value = kCostmapUnknown;
  return interpretation;
}

// The grid made afresh from the whole costmap, as every plan made it before the mirror.
std::vector<std::uint8_t> freshGridBytes(const CostmapSnapshot& costmap) {
  const eaci::GridView view(costmap.cells.data(), costmap.frame.width, costmap.frame.height, costmap.order,
                            costmapInterpretation());
  const eaci::CostGrid grid = eaci::CostGrid::fromView(view, false);
  return {grid.cellBytes(), grid.cellBytes() + grid.cellCount()};
}

std::vector<std::uint8_t> bytesOf(const eaci::CostGrid& grid) {
  return {grid.cellBytes(), grid.cellBytes() + grid.cellCount()};
}

TEST(CostmapMirror, MatchesAFreshGridAfterEveryChangeToldOrNot) {
  for (const bool told : {true, false}) {
    std::mt19937 random(5);
    CostmapSnapshot costmap = randomCostmap(37, 23, random);
    CostmapMirror mirror;
    const auto sync = [&](const CostmapChanges& changes) {
      return mirror.sync(CostmapView::of(costmap), changes, costmapInterpretation(), false, {});
    };
    EXPECT_TRUE(sync(CostmapChanges::none()).afresh);  // the first: made afresh, whatever it is told
    ASSERT_EQ(bytesOf(mirror.grid()), freshGridBytes(costmap));
    std::uniform_int_distribution<int> x(0, 36), y(0, 22), value(0, 255), count(0, 4);
    for (int round = 0; round < 200; ++round) {
      CostmapChanges changes = told ? CostmapChanges::none() : CostmapChanges::unknown();
      for (int k = count(random); k > 0; --k) {
        const int cx = x(random), cy = y(random);
        costmap.cells[static_cast<std::size_t>(cy) * 37 + cx] = static_cast<std::uint8_t>(value(random));
        if (told) changes.rects.push_back({cx, cy, cx + 1, cy + 1});
      }
      const CostmapMirror::Sync synced = sync(changes);
      EXPECT_FALSE(synced.afresh);
      ASSERT_EQ(mirror.costmap().cells, costmap.cells) << "round " << round << (told ? " told" : " untold");
      ASSERT_EQ(bytesOf(mirror.grid()), freshGridBytes(costmap)) << "round " << round << (told ? " told" : " untold");
    }
  }
}

TEST(CostmapMirror, ToldNothingItReadsOnlyItsAuditRowAndNumbersOnlyTheRowsThatChanged) {
  std::mt19937 random(3);
  CostmapSnapshot costmap = randomCostmap(10, 8, random);
  CostmapMirror mirror(10);  // audits one row (10 bytes) a sync
  const auto sync = [&](const CostmapChanges& changes) {
    return mirror.sync(CostmapView::of(costmap), changes, costmapInterpretation(), false, {});
  };
  sync(CostmapChanges::none());
  const std::vector<std::uint8_t> before = bytesOf(mirror.grid());
  std::vector<std::uint64_t> changes_before;
  for (int r = 0; r < 8; ++r) changes_before.push_back(mirror.grid().rowChange(r));

  // Buffer row 1 is grid row 6 (bottom first). Told nothing: the first sync audits buffer row
  // 0 only, so the copy keeps what it had.
  costmap.cells[1 * 10 + 4] = costmap.cells[1 * 10 + 4] == 0 ? 254 : 0;
  const CostmapMirror::Sync first = sync(CostmapChanges::none());
  EXPECT_EQ(first.rows_read, 1u);
  EXPECT_EQ(first.rows_missed, 0u);
  EXPECT_EQ(bytesOf(mirror.grid()), before);
  // Told a rectangle that holds it: read (3 rows and the audit's row 1, already synced), and
  // only grid row 6 gets a new change number.
  CostmapChanges changes = CostmapChanges::none();
  changes.rects.push_back({2, 0, 6, 3});  // buffer rows 0..2
  const CostmapMirror::Sync told = sync(changes);
  EXPECT_EQ(told.rows_read, 4u);
  EXPECT_EQ(told.rows_changed, 1u);
  EXPECT_EQ(told.rows_missed, 0u);
  EXPECT_EQ(bytesOf(mirror.grid()), freshGridBytes(costmap));
  for (int r = 0; r < 8; ++r) {
    if (r == 6) EXPECT_GT(mirror.grid().rowChange(r), changes_before[static_cast<std::size_t>(r)]);
    else EXPECT_EQ(mirror.grid().rowChange(r), changes_before[static_cast<std::size_t>(r)]) << "row " << r;
  }
}

// A change its keeper never reports is found by the audit within one round of the map.
TEST(CostmapMirror, TheAuditFindsAChangeNobodyReported) {
  std::mt19937 random(4);
  CostmapSnapshot costmap = randomCostmap(10, 8, random);
  CostmapMirror mirror(20);  // two rows a sync
  mirror.sync(CostmapView::of(costmap), CostmapChanges::none(), costmapInterpretation(), false, {});
  costmap.cells[7 * 10 + 9] = costmap.cells[7 * 10 + 9] == 0 ? 254 : 0;  // buffer row 7
  std::size_t missed = 0;
  for (int k = 0; k < 4; ++k)  // rows 2-3, 4-5, 6-7, ...: found on the third sync
    missed += mirror.sync(CostmapView::of(costmap), CostmapChanges::none(), costmapInterpretation(), false, {}).rows_missed;
  EXPECT_EQ(missed, 1u);
  EXPECT_EQ(bytesOf(mirror.grid()), freshGridBytes(costmap));
}

// A plan's time limit counts from the caller's entry, the first copy of a large costmap
// included: a sync stopped part-way keeps the rows made; the next one compares those (they
// may have changed since) and makes the rest.
TEST(CostmapMirror, ASyncStoppedPartWayIsFinishedByTheNext) {
  std::mt19937 random(5);
  CostmapSnapshot costmap = randomCostmap(1024, 200, random);  // asked after every 64 rows of 1024 bytes
  CostmapMirror mirror;
  int asked = 0;
  const std::function<bool()> second_question = [&asked] { return ++asked == 2; };  // after 128 rows
  const CostmapMirror::Sync stopped = mirror.sync(CostmapView::of(costmap), CostmapChanges::none(),
                                                  costmapInterpretation(), false, {}, second_question);
  EXPECT_TRUE(stopped.stopped);
  EXPECT_EQ(stopped.rows_read, 128u);
  costmap.cells[10 * 1024 + 5] ^= 0x55;   // a row made before the stop
  costmap.cells[170 * 1024 + 7] ^= 0x55;  // a row not yet made
  const CostmapMirror::Sync finished =
      mirror.sync(CostmapView::of(costmap), CostmapChanges::unknown(), costmapInterpretation(), false, {});
  EXPECT_FALSE(finished.stopped);
  EXPECT_EQ(finished.rows_read, 200u);
  EXPECT_EQ(bytesOf(mirror.grid()), freshGridBytes(costmap));
  EXPECT_EQ(mirror.costmap().cells, costmap.cells);
  const CostmapMirror::Sync next =
      mirror.sync(CostmapView::of(costmap), CostmapChanges::none(), costmapInterpretation(), false, {});
  EXPECT_FALSE(next.afresh);  // made: from now on only what changed
}

TEST(CostmapMirror, ANewFrameOrInterpretationMakesItAfresh) {
  std::mt19937 random(9);
  CostmapSnapshot costmap = randomCostmap(12, 9, random);
  CostmapMirror mirror;
  const auto sync = [&](const eaci::CellInterpretation& interpretation, bool corners) {
    return mirror.sync(CostmapView::of(costmap), CostmapChanges::none(), interpretation, corners, {});
  };
  EXPECT_TRUE(sync(costmapInterpretation(), false).afresh);
  EXPECT_FALSE(sync(costmapInterpretation(), false).afresh);
  costmap.frame.origin.x() += 0.05;  // the costmap moved: every cell may be another
  EXPECT_TRUE(sync(costmapInterpretation(), false).afresh);
  EXPECT_TRUE(sync(eaci::CellInterpretation::costmap(200, false), false).afresh);
  EXPECT_TRUE(sync(eaci::CellInterpretation::costmap(200, false), true).afresh);
  const eaci::GridView view(costmap.cells.data(), 12, 9, costmap.order, eaci::CellInterpretation::costmap(200, false));
  const eaci::CostGrid expected = eaci::CostGrid::fromView(view, true);
  EXPECT_EQ(bytesOf(mirror.grid()), bytesOf(expected));
}

TEST(CostmapMirror, OpenedCellsLastOnePlan) {
  std::mt19937 random(2);
  CostmapSnapshot costmap = randomCostmap(6, 5, random);
  costmap.cells[2 * 6 + 3] = kCostmapInscribed;  // buffer row 2 = grid row 2 (5 rows, bottom first)
  CostmapMirror mirror;
  mirror.sync(CostmapView::of(costmap), CostmapChanges::none(), costmapInterpretation(), false, {});
  mirror.open(eaci::Cell{2, 3}, 252);
  EXPECT_EQ(mirror.costmap().cells[2 * 6 + 3], 252);
  EXPECT_FALSE(mirror.grid().isBlocked(eaci::Cell{2, 3}));
  mirror.sync(CostmapView::of(costmap), CostmapChanges::none(), costmapInterpretation(), false, {});
  EXPECT_EQ(mirror.costmap().cells[2 * 6 + 3], kCostmapInscribed);
  EXPECT_TRUE(mirror.grid().isBlocked(eaci::Cell{2, 3}));
  EXPECT_EQ(bytesOf(mirror.grid()), freshGridBytes(costmap));
}

// A caller whose reports missed a change is not trusted again: the service says so once and
// compares every row from then on.
TEST(CostmapMirror, TheServiceStopsTrustingReportsThatMissedAChange) {
  std::vector<std::string> warnings;
  PlanningService service(ServiceSettings{}, [&warnings](LogLevel level, const std::string& line) {
    if (level == LogLevel::kWarn) warnings.push_back(line);
  });
  test::configure(service, test::configuration(eaci::Algorithm::kAStar));
  CostmapSnapshot costmap = test::openCostmap(30, 20);
  const PlanRequest request = test::request(costmap, {10, 2}, {10, 27});
  ASSERT_TRUE(service.plan(CostmapView::of(costmap), request, CostmapChanges::none()).ok());
  for (int row = 5; row <= 15; ++row) test::at(costmap, row, 15) = kCostmapLethal;  // not reported
  const PlanReply reply = service.plan(CostmapView::of(costmap), request, CostmapChanges::none());
  ASSERT_TRUE(reply.ok()) << reply.error;
  EXPECT_EQ(test::routeDefect(costmap, reply.result.path, {10, 2}, {10, 27}), "");  // the audit read the whole small map
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("did not report"), std::string::npos) << warnings[0];
  test::at(costmap, 3, 3) = kCostmapLethal;  // another change not reported: compared anyway, said no more
  const PlanReply next = service.plan(CostmapView::of(costmap), request, CostmapChanges::none());
  ASSERT_TRUE(next.ok()) << next.error;
  EXPECT_EQ(next.phases.rows_changed, 1u);
  EXPECT_EQ(warnings.size(), 1u);
}

// Through the service: a wall put on the last route, anywhere along it, is avoided by the next
// plan, told by a rectangle or not; and each plan is the one eaci::plan makes on a fresh grid of
// the costmap as it is (EACI with its seed, A*).
TEST(CostmapMirror, AChangeAnywhereIsSeenByTheNextPlanAndPlansStayTheSame) {
  for (const eaci::Algorithm algorithm : {eaci::Algorithm::kAStar, eaci::Algorithm::kEaci}) {
    for (const bool told : {true, false}) {
      PlanningService service(ServiceSettings{}, Logger{});
      const PlanningService::Configuration config = test::configuration(algorithm);
      test::configure(service, config);
      CostmapSnapshot costmap = test::openCostmap(60, 40);
      const PlanRequest request = test::request(costmap, {20, 2}, {20, 57});
      std::mt19937 random(told ? 1 : 2);
      for (int round = 0; round < 12; ++round) {
        const PlanReply reply =
            service.plan(CostmapView::of(costmap), request, round == 0 || !told ? CostmapChanges::unknown() : CostmapChanges::none());
        ASSERT_TRUE(reply.ok()) << reply.error;
        EXPECT_EQ(test::routeDefect(costmap, reply.result.path, {20, 2}, {20, 57}), "");
        // The same plan on a grid made afresh from the costmap.
        const eaci::GridView view(costmap.cells.data(), 60, 40, costmap.order, costmapInterpretation());
        const eaci::PlanResult fresh = eaci::plan(view, {20, 2}, {20, 57}, algorithm, config.params);
        ASSERT_TRUE(fresh.success());
        EXPECT_EQ(reply.result.path, fresh.path) << "round " << round;
        EXPECT_EQ(reply.result.iterations_run, fresh.iterations_run);
        // A wall of three cells across the route, somewhere along it, for the next plan.
        const eaci::CellPath& path = reply.result.path;
        const eaci::Cell on = path[std::uniform_int_distribution<std::size_t>(1, path.size() - 2)(random)];
        CostmapChanges changes = CostmapChanges::none();
        for (int dr = -1; dr <= 1; ++dr) {
          const int row = on.row + dr;
          if (row < 0 || row >= 40 || (row == 20 && (on.col == 2 || on.col == 57))) continue;
          test::at(costmap, row, on.col) = kCostmapLethal;
        }
        const PlanReply next = service.plan(CostmapView::of(costmap), request,
                                            told ? CostmapChanges{true, {{on.col, std::max(0, on.row - 1),
                                                                          on.col + 1, std::min(40, on.row + 2)}}}
                                                 : CostmapChanges::unknown());
        ASSERT_TRUE(next.ok()) << next.error;
        EXPECT_EQ(test::routeDefect(costmap, next.result.path, {20, 2}, {20, 57}), "") << "round " << round;
      }
    }
  }
}

}  // namespace
}  // namespace eaci_service
