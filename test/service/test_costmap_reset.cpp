// A costmap that costmap_2d emptied (resized or cleared, not yet filled) is planned on as the last
// filled one showed it (costmap_reset.hpp). Expectations are written out cell by cell.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "costmap_reset.hpp"
#include "service_test_support.hpp"

namespace eaci_service {
namespace {

using Clock = EmptiedCostmapStandIn::Clock;

// A bottom-first costmap of `width` x rows.size() cells; rows given top row first, as drawn.
CostmapSnapshot costmapOf(const std::vector<std::vector<int>>& top_first, double ox = 0.0, double oy = 0.0) {
  CostmapSnapshot c;
  c.frame.height = static_cast<int>(top_first.size());
  c.frame.width = static_cast<int>(top_first.front().size());
  c.frame.resolution = 0.5;
  c.frame.origin = {ox, oy};
  c.frame_id = "map";
  for (int r = c.frame.height - 1; r >= 0; --r)
    for (int v : top_first[static_cast<std::size_t>(r)]) c.cells.push_back(static_cast<std::uint8_t>(v));
  return c;
}

CostmapSnapshot uniform(int width, int height, std::uint8_t value, double ox = 0.0, double oy = 0.0) {
  return costmapOf(std::vector<std::vector<int>>(static_cast<std::size_t>(height),
                                                 std::vector<int>(static_cast<std::size_t>(width), value)),
                   ox, oy);
}

TEST(CostmapReset, UniformMeansEveryCellTheSame) {
  EXPECT_TRUE(isUniform(uniform(3, 2, 255)));
  EXPECT_TRUE(isUniform(uniform(1, 1, 0)));
  EXPECT_FALSE(isUniform(costmapOf({{0, 0, 0}, {0, 0, 254}})));  // the last cell differs
  EXPECT_FALSE(isUniform(CostmapSnapshot{}));                      // no cell: nothing emptied
}

TEST(CostmapReset, AGrownMapHoldsTheOldOneWhereItLies) {
  // Old: 2 x 2 cells at (0, 0). New: 4 x 3 cells at (-0.5, -0.5), one cell further left and
  // down: the old bottom-left cell lands on new column 1, second row from the bottom.
  const CostmapSnapshot old = costmapOf({{1, 2},
                                         {3, 4}});
  eaci::MapFrame frame = old.frame;
  frame.width = 4;
  frame.height = 3;
  frame.origin = {-0.5, -0.5};
  const auto placed = placedInto(old, frame, 255);
  ASSERT_TRUE(placed);
  EXPECT_EQ(placed->cells, costmapOf({{255, 1, 2, 255},
                                      {255, 3, 4, 255},
                                      {255, 255, 255, 255}}, -0.5, -0.5).cells);
}

TEST(CostmapReset, AShrunkOrShiftedMapKeepsTheOverlapOnly) {
  const CostmapSnapshot old = costmapOf({{1, 2, 3},
                                         {4, 5, 6}});
  eaci::MapFrame frame = old.frame;
  frame.width = 2;
  frame.height = 2;
  frame.origin = {1.0, 0.5};  // two cells right, one up: old (top row, col 2) lands on new (bottom row, col 0)
  const auto placed = placedInto(old, frame, 0);
  ASSERT_TRUE(placed);
  EXPECT_EQ(placed->cells, costmapOf({{0, 0},
                                      {3, 0}}, 1.0, 0.5).cells);
}

TEST(CostmapReset, NothingLinesUpAcrossResolutionsOrFractionalShifts) {
  const CostmapSnapshot old = costmapOf({{1, 2}, {3, 4}});
  eaci::MapFrame frame = old.frame;
  frame.resolution = 0.25;
  EXPECT_FALSE(placedInto(old, frame, 0));
  frame = old.frame;
  frame.origin = {0.25, 0.0};  // half a cell
  EXPECT_FALSE(placedInto(old, frame, 0));
}

TEST(CostmapReset, AnEmptiedCostmapIsPlannedOnAsTheLastFilledOneShowedIt) {
  EmptiedCostmapStandIn stand_in(std::chrono::seconds(3));
  const Clock::time_point t0{};
  const CostmapSnapshot filled = costmapOf({{0, 254}, {0, 0}});
  std::string said;
  EXPECT_FALSE(stand_in.standIn(CostmapView::of(filled), &filled, t0, said));  // a filled costmap is planned on
  EXPECT_EQ(said, "");

  // Resized to 3 x 2 (one column more on the right) and emptied to unknown.
  const CostmapSnapshot emptied = uniform(3, 2, 255);
  const auto placed = stand_in.standIn(CostmapView::of(emptied), &filled, t0 + std::chrono::seconds(1), said);
  ASSERT_TRUE(placed);
  EXPECT_NE(said.find("holds 255 in every cell"), std::string::npos) << said;
  EXPECT_EQ(placed->frame.width, 3);
  EXPECT_EQ(placed->cells, costmapOf({{0, 254, 255}, {0, 0, 255}}).cells);
}

TEST(CostmapReset, AnEmptyMapIsPlannedOnAsItIsWhenNothingWasFilledOrTheWaitRanOut) {
  EmptiedCostmapStandIn stand_in(std::chrono::seconds(3));
  const Clock::time_point t0{};
  std::string said;
  const CostmapSnapshot empty = uniform(2, 2, 0);
  EXPECT_FALSE(stand_in.standIn(CostmapView::of(empty), nullptr, t0, said));  // nothing filled was ever seen

  const CostmapSnapshot filled = costmapOf({{0, 254}, {0, 0}});
  EXPECT_FALSE(stand_in.standIn(CostmapView::of(filled), &filled, t0, said));
  EXPECT_TRUE(stand_in.standIn(CostmapView::of(empty), &filled, t0 + std::chrono::seconds(1), said));  // the wait starts here
  EXPECT_TRUE(stand_in.standIn(CostmapView::of(empty), &filled, t0 + std::chrono::seconds(4), said));  // 3 s after the first
  EXPECT_FALSE(stand_in.standIn(CostmapView::of(empty), &filled, t0 + std::chrono::milliseconds(4001), said));  // past 3 s
}

// Through the service, as move_base's planner sees a SLAM map grow: a plan on a 10 x 5 costmap
// with a wall down column 5 (rows 0-3; the way round is row 4), then the costmap resized to
// 12 x 5 and emptied to unknown (every cell 255) before its update. From (2, 1) to (2, 8) the
// only routes round the wall pass row 4; a straight line crosses it at row 2.
bool crossesTheWall(const eaci::CellPath& path) {
  for (const eaci::Cell& c : path)
    if (c.col == 5 && c.row <= 3) return true;
  return false;
}

PlanReply planOnAGrownEmptiedCostmap(bool stand_in) {
  ServiceSettings settings;
  settings.stand_in_for_emptied_costmaps = stand_in;
  PlanningService service(settings, Logger{});
  test::configure(service, test::configuration(eaci::Algorithm::kAStar));
  CostmapSnapshot filled = test::openCostmap(10, 5);
  for (int row = 0; row <= 3; ++row) test::at(filled, row, 5) = kCostmapLethal;
  const PlanReply first = service.plan(filled, test::request(filled, {2, 1}, {2, 8}));
  EXPECT_TRUE(first.ok()) << first.error;
  EXPECT_FALSE(crossesTheWall(first.result.path));
  CostmapSnapshot emptied = test::openCostmap(12, 5);
  std::fill(emptied.cells.begin(), emptied.cells.end(), kCostmapUnknown);
  return service.plan(emptied, test::request(emptied, {2, 1}, {2, 8}));
}

TEST(CostmapReset, APlanOnAnEmptiedCostmapKeepsToTheWallsTheLastOneShowed) {
  const PlanReply reply = planOnAGrownEmptiedCostmap(true);
  ASSERT_TRUE(reply.ok()) << reply.error;
  EXPECT_FALSE(crossesTheWall(reply.result.path));
  EXPECT_FALSE(crossesTheWall(reply.result.smoothed_path));
  EXPECT_EQ(reply.frame.width, 12);
}

TEST(CostmapReset, WithoutTheStandInTheEmptiedCostmapShowsNoWall) {  // what the stand-in is for
  const PlanReply reply = planOnAGrownEmptiedCostmap(false);
  ASSERT_TRUE(reply.ok()) << reply.error;
  EXPECT_TRUE(crossesTheWall(reply.result.path));
}

}  // namespace
}  // namespace eaci_service
