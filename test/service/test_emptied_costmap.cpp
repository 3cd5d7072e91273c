// A costmap that costmap_2d emptied (resized or cleared, not yet filled) is planned on as the last
// filled one showed it (emptied_costmap.hpp). Expectations are written out cell by cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "emptied_costmap.hpp"
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

TEST(EmptiedCostmap, UniformMeansEveryCellTheSame) {
  EXPECT_TRUE(isUniform(uniform(3, 2, 255)));
  EXPECT_TRUE(isUniform(uniform(1, 1, 0)));
  EXPECT_FALSE(isUniform(costmapOf({{0, 0, 0}, {0, 0, 254}})));  // the last cell differs
  EXPECT_FALSE(isUniform(CostmapSnapshot{}));                      // no cell: nothing emptied
}

TEST(EmptiedCostmap, AGrownMapHoldsTheOldOneWhereItLies) {
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

TEST(EmptiedCostmap, AShrunkOrShiftedMapKeepsTheOverlapOnly) {
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

TEST(EmptiedCostmap, NothingLinesUpAcrossResolutionsOrFractionalShifts) {
  const CostmapSnapshot old = costmapOf({{1, 2}, {3, 4}});
  eaci::MapFrame frame = old.frame;
  frame.resolution = 0.25;
  EXPECT_FALSE(placedInto(old, frame, 0));
  frame = old.frame;
  frame.origin = {0.25, 0.0};  // half a cell
  EXPECT_FALSE(placedInto(old, frame, 0));
}

TEST(EmptiedCostmap, ACostmapEmptiedByAResizeIsPlannedOnAsTheLastFilledOneShowedIt) {
  EmptiedCostmapStandIn stand_in(std::chrono::seconds(3));
  const Clock::time_point t0{};
  const CostmapSnapshot filled = costmapOf({{0, 254}, {0, 0}});
  std::string said;
  EXPECT_FALSE(stand_in.standIn(CostmapView::of(filled), &filled, t0, t0, said));  // a filled costmap is planned on
  EXPECT_EQ(said, "");

  // Resized to 3 x 2 (one column more on the right) and emptied to unknown.
  const CostmapSnapshot emptied = uniform(3, 2, 255);
  const auto placed = stand_in.standIn(CostmapView::of(emptied), &filled, t0, t0 + std::chrono::seconds(1), said);
  ASSERT_TRUE(placed);
  EXPECT_NE(said.find("was resized and holds 255 in every cell"), std::string::npos) << said;
  EXPECT_NE(said.find("read 1000 ms ago"), std::string::npos) << said;
  EXPECT_EQ(placed->frame.width, 3);
  EXPECT_EQ(placed->cells, costmapOf({{0, 254, 255}, {0, 0, 255}}).cells);
}

// Only a resize empties a costmap behind the planner's back: a uniform costmap of the same frame
// (cleared by ~clear_costmaps, a costmap without a static layer, an empty world) is planned on
// as it is; and the last filled one stands in only while it was read at most max_age ago.
TEST(EmptiedCostmap, AUniformCostmapOfTheSameFrameOrOldDataIsPlannedOnAsItIs) {
  EmptiedCostmapStandIn stand_in(std::chrono::seconds(3));
  const Clock::time_point t0{};
  std::string said;
  const CostmapSnapshot filled = costmapOf({{0, 254}, {0, 0}});
  const CostmapSnapshot cleared = uniform(2, 2, 0);  // the same 2 x 2 frame
  EXPECT_FALSE(stand_in.standIn(CostmapView::of(cleared), &filled, t0, t0, said));
  EXPECT_FALSE(stand_in.lastWasFilled());
  const CostmapSnapshot grown = uniform(3, 2, 0);
  EXPECT_FALSE(stand_in.standIn(CostmapView::of(grown), nullptr, t0, t0, said));  // nothing filled was ever seen
  EXPECT_TRUE(stand_in.standIn(CostmapView::of(grown), &filled, t0, t0 + std::chrono::seconds(3), said));
  EXPECT_FALSE(stand_in.standIn(CostmapView::of(grown), &filled, t0, t0 + std::chrono::milliseconds(3001), said));
}

// Through the service, as move_base's planner sees a SLAM map grow: a plan on a 10 x 5 costmap
// with a wall down column 5 (rows 0-3; the way round is row 4), then the costmap resized to
// 12 x 5 and emptied to unknown (every cell 255) before its update. From (2, 1) to (2, 8) the
// only routes round the wall pass row 4; a straight line crosses it at row 2.
// Whether any segment between two of the poses sent passes the wall (x in [5, 6) m, y from 1 m
// up: column 5, rows 0-3), sampled every centimetre: a straight line through the wall has no
// pose in it.
bool posesCrossTheWall(const std::vector<Eigen::Vector2d>& poses) {
  for (std::size_t k = 1; k < poses.size(); ++k) {
    const Eigen::Vector2d a = poses[k - 1], b = poses[k];
    const int samples = std::max(1, static_cast<int>((b - a).norm() * 100));
    for (int i = 0; i <= samples; ++i) {
      const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(i) / samples);
      if (p.x() >= 5.0 && p.x() < 6.0 && p.y() >= 1.0) return true;
    }
  }
  return false;
}

// The first plan on the filled costmap, then one on `next`.
PlanReply planAgainOn(bool stand_in, const CostmapSnapshot& next) {
  ServiceSettings settings;
  settings.stand_in_for_emptied_costmaps = stand_in;
  PlanningService service(settings, Logger{});
  test::configure(service, test::configuration(eaci::Algorithm::kAStar));
  CostmapSnapshot filled = test::openCostmap(10, 5);
  for (int row = 0; row <= 3; ++row) test::at(filled, row, 5) = kCostmapLethal;
  const PlanReply first = service.plan(filled, test::request(filled, {2, 1}, {2, 8}));
  EXPECT_TRUE(first.ok()) << first.error;
  EXPECT_FALSE(posesCrossTheWall(first.poses));
  return service.plan(next, test::request(next, {2, 1}, {2, 8}));
}

CostmapSnapshot emptiedAndGrown() {
  CostmapSnapshot emptied = test::openCostmap(12, 5);
  std::fill(emptied.cells.begin(), emptied.cells.end(), kCostmapUnknown);
  return emptied;
}

TEST(EmptiedCostmap, APlanOnAnEmptiedCostmapKeepsToTheWallsTheLastOneShowed) {
  const PlanReply reply = planAgainOn(true, emptiedAndGrown());
  ASSERT_TRUE(reply.ok()) << reply.error;
  EXPECT_TRUE(reply.stood_in_for_emptied);
  EXPECT_FALSE(posesCrossTheWall(reply.poses));
  EXPECT_EQ(reply.frame.width, 12);
}

TEST(EmptiedCostmap, WithoutTheStandInTheEmptiedCostmapShowsNoWall) {  // what the stand-in is for
  const PlanReply reply = planAgainOn(false, emptiedAndGrown());
  ASSERT_TRUE(reply.ok()) << reply.error;
  EXPECT_FALSE(reply.stood_in_for_emptied);
  EXPECT_TRUE(posesCrossTheWall(reply.poses));
}

// A costmap of the same frame that is uniform (cleared, or a world with nothing in it) is
// planned on as it is: no phantom wall.
TEST(EmptiedCostmap, AClearedCostmapOfTheSameFrameIsPlannedOnAsItIs) {
  const PlanReply reply = planAgainOn(true, test::openCostmap(10, 5));
  ASSERT_TRUE(reply.ok()) << reply.error;
  EXPECT_FALSE(reply.stood_in_for_emptied);
  EXPECT_TRUE(posesCrossTheWall(reply.poses));
}

}  // namespace
}  // namespace eaci_service
