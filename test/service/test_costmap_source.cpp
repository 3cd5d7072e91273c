// Where a plan's costmap comes from (src/service/costmap_source.hpp): no way for the planner's
// copy to fall behind the costmap. Each test reads a 1000 x 1000 costmap, whose mirror audits
// only 65 rows a read (64 KiB), so a change the reads should see and do not stays unseen; the
// expectations are the costmap's own bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "costmap_source.hpp"
#include "service_test_support.hpp"

namespace eaci_service {
namespace {

using Clock = CostmapSource::Clock;
constexpr int kSide = 1000;

eaci::CellInterpretation interpretation() {
  eaci::CellInterpretation i = eaci::CellInterpretation::costmap(253, true);
  i.unknown_value = kCostmapUnknown;
  return i;
}

struct Source {
  std::vector<std::string> said;
  CostmapSource source;
  explicit Source(bool stand_in = false)
      : source({stand_in, 5.0}, [this](const std::string& line, bool) { said.push_back(line); }) {}
  CostmapSource::Read read(const CostmapSnapshot& costmap, const CostmapChanges& changes,
                           Clock::time_point now = Clock::time_point{}) {
    return source.read(CostmapView::of(costmap), changes, interpretation(), false, eaci::CostRule{}, false, now);
  }
};

CostmapSnapshot bigCostmap() { return test::openCostmap(kSide, kSide); }

// A wall across buffer row `y` (the keeper's rectangle for it).
BufferRect wallAcross(CostmapSnapshot& costmap, int y) {
  for (int x = 0; x < kSide; ++x) costmap.cells[static_cast<std::size_t>(y) * kSide + x] = kCostmapLethal;
  return {0, y, kSide, y + 1};
}

CostmapChanges reported(const BufferRect& rect) { return {true, {rect}}; }

// Changes handed to a plan that was refused before it read them (a pose in another frame, a bad
// parameter, the turn's wait ran out) are not lost: the next read compares every row.
TEST(CostmapSource, ChangesTakenButNotReadAreReadByTheNextPlan) {
  Source s;
  CostmapSnapshot costmap = bigCostmap();
  s.read(costmap, CostmapChanges::none());  // made afresh
  wallAcross(costmap, 500);                  // reported to a plan that never read it
  s.source.changesNotRead();
  const CostmapSource::Read read = s.read(costmap, CostmapChanges::none());  // the keeper reports nothing new
  EXPECT_EQ(read.mirror->costmap().cells, costmap.cells);
  EXPECT_EQ(read.synced.rows_read, static_cast<std::size_t>(kSide));
}

// A read of a copy (~make_plan's, taken before its turn) may be older than what a plan read
// before it; the keeper will not report those rows again, so the next read compares them all.
TEST(CostmapSource, AnOlderCopyCannotLeaveTheNextPlanBehind) {
  Source s;
  CostmapSnapshot costmap = bigCostmap();
  const CostmapSnapshot older = costmap;
  s.read(costmap, CostmapChanges::none());
  const BufferRect wall = wallAcross(costmap, 500);
  s.read(costmap, reported(wall));          // a plan reads the wall where the keeper says
  s.read(older, CostmapChanges::unknown()); // ~make_plan's copy from before the wall
  const CostmapSource::Read read = s.read(costmap, CostmapChanges::none());
  EXPECT_EQ(read.mirror->costmap().cells, costmap.cells);
}

// A write the keeper missed (found by the audit) gets every row compared for the next
// kDistrustedReads reads, counted and said, then the keeper's reports are trusted again.
TEST(CostmapSource, AMissedWriteIsDistrustedForABoundedNumberOfPlans) {
  Source s;
  CostmapSnapshot costmap = bigCostmap();
  s.read(costmap, CostmapChanges::none());
  wallAcross(costmap, 10);  // not reported; the first known read audits rows 0..64
  const CostmapSource::Read found = s.read(costmap, CostmapChanges::none());
  EXPECT_EQ(found.synced.rows_missed, 1u);
  EXPECT_EQ(s.source.missedWrites(), 1u);
  ASSERT_EQ(s.said.size(), 1u);
  EXPECT_NE(s.said[0].find("the next 20 plans compare every row (1 such changes so far)"), std::string::npos) << s.said[0];
  for (int k = 0; k < CostmapSource::kDistrustedReads; ++k)
    EXPECT_EQ(s.read(costmap, CostmapChanges::none()).synced.rows_read, static_cast<std::size_t>(kSide)) << k;
  EXPECT_LT(s.read(costmap, CostmapChanges::none()).synced.rows_read, static_cast<std::size_t>(kSide));
}

// The stand-in for a costmap emptied by a resize is the last filled one as costmap_2d showed it,
// not with the cells the last plan opened for its start (a robot in the band).
TEST(CostmapSource, TheStandInHoldsNoCellOpenedForTheLastStart) {
  Source s(true);
  CostmapSnapshot costmap = test::openCostmap(40, 30);
  test::at(costmap, 7, 9) = kCostmapLethal;
  const Clock::time_point t0{};
  CostmapSource::Read read = s.read(costmap, CostmapChanges::unknown(), t0);
  read.mirror->open({7, 9}, 0);  // the last plan's way out of the band
  CostmapSnapshot grown = test::openCostmap(41, 30);
  std::fill(grown.cells.begin(), grown.cells.end(), kCostmapUnknown);
  read = s.read(grown, CostmapChanges::unknown(), t0 + std::chrono::seconds(1));
  ASSERT_TRUE(read.stood_in);
  const CostmapSnapshot& stood_in = read.mirror->costmap();  // bottom row first
  EXPECT_EQ(stood_in.cells[stood_in.bufferIndex({7, 9})], kCostmapLethal);
  ASSERT_EQ(s.said.size(), 1u);
  EXPECT_NE(s.said[0].find("was resized"), std::string::npos) << s.said[0];
}

}  // namespace
}  // namespace eaci_service
