// The last check of the route that goes out (src/service/route_defect.hpp): every cell a
// smoothed segment passes, against cells worked out by hand below.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "costmap_snapshot.hpp"
#include "route_defect.hpp"

namespace {

using eaci::Cell;
using eaci_service::drivableRouteDefect;
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

}  // namespace
