// The last check of the route that goes out (src/service/route_defect.hpp): every cell a
// smoothed segment passes, against cells worked out by hand below.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "costmap_snapshot.hpp"
#include "route_defect.hpp"
#include "route_finish.hpp"

namespace {

using eaci::Cell;
using eaci_service::drivableRouteDefect;
using eaci_service::polylineDefect;
using eaci_service::routeDefect;

// A costmap_2d-style map of `rows` ('.' free 0, '#' lethal 254, '?' unknown 255), top row
// first, read with lethal_cost 253 and allow_unknown as given.
struct Map {
  std::vector<std::uint8_t> bytes;
  int width = 0, height = 0;
  explicit Map(const std::vector<std::string>& rows) : width(static_cast<int>(rows[0].size())), height(static_cast<int>(rows.size())) {
    for (const std::string& row : rows)
      for (char c : row) bytes.push_back(c == '#' ? eaci_service::kCostmapLethal : c == '?' ? eaci_service::kCostmapUnknown : 0);
  }
  eaci::GridView view(bool allow_unknown = true) const {
    return eaci::GridView(bytes.data(), width, height, eaci::RowOrder::kTopFirst,
                          eaci::CellInterpretation::costmap(253, allow_unknown));
  }
};

TEST(DrivableRoute, StraightAndDiagonalSegmentsOverFreeCellsPass) {
  const Map map({
      ".....",
      ".....",
      ".....",
  });
  EXPECT_EQ(drivableRouteDefect(map.view(), {{0, 0}, {0, 4}, {2, 2}}, {0, 0}, {2, 2}, false), "");
  EXPECT_EQ(drivableRouteDefect(map.view(), {{1, 1}}, {1, 1}, {1, 1}, false), "");  // start = goal
}

TEST(DrivableRoute, ASegmentThroughABlockedCellIsNamed) {
  const Map map({
      ".....",
      "..#..",
      ".....",
  });
  EXPECT_EQ(drivableRouteDefect(map.view(), {{0, 0}, {1, 0}, {1, 4}}, {0, 0}, {1, 4}, false),
            "segment 2 of 2, (row 1, col 0) to (row 1, col 4): it crosses the blocked cell (row 1, col 2)");
  // Unknown cells count as the view reads them.
  const Map unknown({"..?.."});
  EXPECT_EQ(drivableRouteDefect(unknown.view(true), {{0, 0}, {0, 4}}, {0, 0}, {0, 4}, false), "");
  EXPECT_NE(drivableRouteDefect(unknown.view(false), {{0, 0}, {0, 4}}, {0, 0}, {0, 4}, false), "");
}

TEST(DrivableRoute, EveryCellOfASlantedSegmentIsChecked) {
  // From the centre of (0, 0) to the centre of (2, 1): the line crosses the border of rows 0/1
  // at column 0.25 (into (1, 0)), the border of columns 0/1 at row 1 (into (1, 1)), the border
  // of rows 1/2 at column 0.75 (into (2, 1)). It never enters (0, 1) or (2, 0).
  const Map clear({
      ".#",
      "..",
      "#.",
  });
  EXPECT_EQ(drivableRouteDefect(clear.view(), {{0, 0}, {2, 1}}, {0, 0}, {2, 1}, false), "");
  const Map blocked_below({
      "..",
      "#.",
      "..",
  });
  EXPECT_EQ(drivableRouteDefect(blocked_below.view(), {{0, 0}, {2, 1}}, {0, 0}, {2, 1}, false),
            "segment 1 of 1, (row 0, col 0) to (row 2, col 1): it crosses the blocked cell (row 1, col 0)");
  const Map blocked_middle({
      "..",
      ".#",
      "..",
  });
  EXPECT_NE(drivableRouteDefect(blocked_middle.view(), {{0, 0}, {2, 1}}, {0, 0}, {2, 1}, false), "");
}

TEST(DrivableRoute, ThroughACornerBothCellsBesideItMustBeFreeUnlessCornersMayBeCut) {
  // (0, 0) to (2, 2) passes the corners (0.5, 0.5) and (1.5, 1.5) exactly; (1, 2) beside the
  // second one is blocked.
  const Map map({
      "...",
      "..#",
      "...",
  });
  EXPECT_EQ(drivableRouteDefect(map.view(), {{0, 0}, {2, 2}}, {0, 0}, {2, 2}, false),
            "segment 1 of 1, (row 0, col 0) to (row 2, col 2): it passes a blocked cell's corner between "
            "(row 1, col 2) and (row 2, col 1)");
  EXPECT_EQ(drivableRouteDefect(map.view(), {{0, 0}, {2, 2}}, {0, 0}, {2, 2}, true), "");
  // (0, 0) to (2, 6), slope 1/3: at column 1.5 (the border of columns 1/2) the line is at row
  // 0.5 (the border of rows 0/1), a corner, beside which lie (0, 2) and (1, 1); (4.5, 1.5) is
  // the other corner. (1, 1) blocked: a corner cut.
  const Map slanted({
      ".......",
      ".#.....",
      ".......",
  });
  EXPECT_EQ(drivableRouteDefect(slanted.view(), {{0, 0}, {2, 6}}, {0, 0}, {2, 6}, false),
            "segment 1 of 1, (row 0, col 0) to (row 2, col 6): it passes a blocked cell's corner between "
            "(row 0, col 2) and (row 1, col 1)");
  EXPECT_EQ(drivableRouteDefect(slanted.view(), {{0, 0}, {2, 6}}, {0, 0}, {2, 6}, true), "");
  // Back the other way the same corner is passed.
  EXPECT_NE(drivableRouteDefect(slanted.view(), {{2, 6}, {0, 0}}, {2, 6}, {0, 0}, false), "");
}

TEST(DrivableRoute, APolylineThatDoesNotJoinStartAndGoalFails) {
  const Map map({"....."});
  EXPECT_EQ(drivableRouteDefect(map.view(), {}, {0, 0}, {0, 4}, false), "it does not join start and goal");
  EXPECT_EQ(drivableRouteDefect(map.view(), {{0, 0}, {0, 3}}, {0, 0}, {0, 4}, false), "it does not join start and goal");
  EXPECT_EQ(drivableRouteDefect(map.view(), {{0, 1}, {0, 4}}, {0, 0}, {0, 4}, false), "it does not join start and goal");
}

// The grid route's check: 8-neighbour moves only, and a diagonal move past a blocked cell only
// when corners may be cut (the move rule, grid/moves.hpp allowedMoves).
TEST(GridRoute, MovesAreOneCellAndKeepTheCornerRule) {
  const Map map({
      "...",
      ".#.",
      "...",
  });
  EXPECT_EQ(routeDefect(map.view(), {{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}}, {0, 0}, {2, 2}, false), "");
  EXPECT_EQ(routeDefect(map.view(), {{0, 0}, {0, 2}, {1, 2}, {2, 2}}, {0, 0}, {2, 2}, false), "it jumps at cell 1");
  EXPECT_EQ(routeDefect(map.view(), {{0, 0}, {0, 0}, {0, 1}}, {0, 0}, {0, 1}, false), "it jumps at cell 1");
  // (0, 1) to (1, 2) passes the corner between the blocked (1, 1) and the free (0, 2).
  const eaci::CellPath cut{{0, 0}, {0, 1}, {1, 2}, {2, 2}};
  EXPECT_EQ(routeDefect(map.view(), cut, {0, 0}, {2, 2}, false),
            "segment 2 of 3, (row 0, col 1) to (row 1, col 2): it passes a blocked cell's corner between "
            "(row 0, col 2) and (row 1, col 1)");
  EXPECT_EQ(routeDefect(map.view(), cut, {0, 0}, {2, 2}, true), "");
  EXPECT_EQ(routeDefect(map.view(), {{0, 0}, {1, 1}, {2, 2}}, {0, 0}, {2, 2}, true),
            "segment 1 of 2, (row 0, col 0) to (row 1, col 1): it crosses the blocked cell (row 1, col 1)");
  EXPECT_EQ(routeDefect(map.view(), {{0, 1}, {0, 2}}, {0, 0}, {0, 2}, false), "it does not join start and goal");
}

// The poses sent: every segment between two points anywhere in the cells, and a point on a
// cell corner touches the cells round it. From (0, 0) to (1, 1) through the corner point
// (col 0.5, row 0.5): (0, 1) beside it is blocked.
TEST(SentPoses, APoseOnACornerTouchesTheCellsRoundIt) {
  const Map map({
      ".#.",
      "...",
      "...",
  });
  const eaci::CellPolyline through_corner{{0.0, 0.0}, {0.5, 0.5}, {1.0, 1.0}};
  EXPECT_EQ(polylineDefect(map.view(), through_corner, false),
            "segment 1 of 2, (row 0, col 0) to (row 0.5, col 0.5): it passes a blocked cell's corner between "
            "(row 0, col 1) and (row 1, col 0)");
  EXPECT_EQ(polylineDefect(map.view(), through_corner, true), "");
  // Off the corner, a point in (1, 0) then (1, 1): nothing blocked is touched.
  EXPECT_EQ(polylineDefect(map.view(), {{0.0, 0.0}, {0.2, 0.8}, {1.0, 1.0}}, false), "");
  // A point that lies in a blocked cell between two free ones.
  EXPECT_EQ(polylineDefect(map.view(), {{0.0, 0.0}, {1.1, 0.2}, {2.0, 0.0}}, false),
            "segment 1 of 2, (row 0, col 0) to (row 0.2, col 1.1): it crosses the blocked cell (row 0, col 1)");
}

// A point on the border of a blocked cell touches it, but the last point (the goal's position)
// lies in its cell however it touches the next; the first must be in a passable cell.
TEST(SentPoses, OnlyTheEndsMayTouchABlockedCellsBorder) {
  const Map map({
      ".#.",
      "...",
  });
  EXPECT_EQ(polylineDefect(map.view(), {{0.0, 1.0}, {1.0, 0.5}}, false), "");  // ends on (0, 1)'s lower border
  EXPECT_EQ(polylineDefect(map.view(), {{0.0, 1.0}, {0.5, 0.0}, {0.0, 0.0}}, false),
            "segment 1 of 2, (row 1, col 0) to (row 0, col 0.5): it touches the blocked cell (row 0, col 1)");
  EXPECT_EQ(polylineDefect(map.view(), {{1.0, 0.0}, {0.0, 1.0}}, false),
            "segment 1 of 1, (row 0, col 1) to (row 1, col 0): it starts in the blocked cell (row 0, col 1)");
  EXPECT_EQ(polylineDefect(map.view(), {}, false), "it has no points");
}

// posesAlong: the robot's position, its cell's centre, a point every cell or less along each
// segment of the route, the goal's position. 1 m cells, 4 x 3, origin (0, 0): the centre of
// (row 2, col 0) is (0.5, 0.5).
TEST(SentPoses, PosesLieAtMostACellApartFromTheRobotToTheGoal) {
  eaci::MapFrame frame;
  frame.width = 4;
  frame.height = 3;
  const auto poses = eaci_service::posesAlong({{2, 0}, {2, 3}}, frame, {0.2, 0.3}, {3.9, 0.2});
  const std::vector<Eigen::Vector2d> expected{{0.2, 0.3}, {0.5, 0.5}, {1.5, 0.5}, {2.5, 0.5}, {3.5, 0.5}, {3.9, 0.2}};
  ASSERT_EQ(poses.size(), expected.size());
  for (std::size_t k = 0; k < poses.size(); ++k) EXPECT_LT((poses[k] - expected[k]).norm(), 1e-12) << k;
  // The diagonal from (row 2, col 0) to (row 0, col 2), 2 sqrt 2 cells: three pieces of 0.943;
  // a start and goal at the centres add no pose.
  const auto diagonal = eaci_service::posesAlong({{2, 0}, {0, 2}}, frame, {0.5, 0.5}, {2.5, 2.5});
  ASSERT_EQ(diagonal.size(), 4u);
  EXPECT_LT((diagonal[1] - Eigen::Vector2d(0.5 + 2.0 / 3, 0.5 + 2.0 / 3)).norm(), 1e-12);
  EXPECT_LT((diagonal[3] - Eigen::Vector2d(2.5, 2.5)).norm(), 1e-12);
  // Start and goal in one cell: two poses.
  EXPECT_EQ(eaci_service::posesAlong({{1, 1}}, frame, {1.5, 1.5}, {1.5, 1.5}).size(), 2u);
  EXPECT_TRUE(eaci_service::posesAlong({}, frame, {1.5, 1.5}, {1.5, 1.5}).empty());
}

}  // namespace
