// Tests of the MovingAI .scen reader (include/eaci/io/movingai_scenario.hpp).
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "eaci/io/movingai_scenario.hpp"
#include "test_support.hpp"

namespace eaci {
namespace {

std::string parseError(const std::string& text) {
  try {
    parseMovingAiScenario(text, "s.scen");
  } catch (const ScenarioLoadError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected a ScenarioLoadError for:\n" << text;
  return "";
}

::testing::AssertionResult has(const std::string& message, std::initializer_list<std::string> parts) {
  return eaci::test::isOneLineWith(message, parts);
}

TEST(MovingAiScenario, ParsesFieldsXIsColumnYIsRow) {
  const auto problems = parseMovingAiScenario(
      "version 1\n"
      "0\tmaps/arena.map\t49\t49\t1\t11\t1\t12\t1\n"
      "3\tmaps/arena.map\t49\t49\t5\t2\t40\t30\t45.52691193\r\n\n");
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].bucket, 0);
  EXPECT_EQ(problems[0].map, "maps/arena.map");
  EXPECT_EQ(problems[0].map_width, 49);
  EXPECT_EQ(problems[0].map_height, 49);
  EXPECT_EQ(problems[0].start, (Cell{11, 1}));  // y 11 = row, x 1 = column
  EXPECT_EQ(problems[0].goal, (Cell{12, 1}));
  EXPECT_EQ(problems[0].optimal_length, 1.0);
  EXPECT_EQ(problems[0].line, 2u);
  EXPECT_EQ(problems[1].bucket, 3);
  EXPECT_EQ(problems[1].start, (Cell{2, 5}));
  EXPECT_EQ(problems[1].goal, (Cell{30, 40}));
  EXPECT_DOUBLE_EQ(problems[1].optimal_length, 45.52691193);
  EXPECT_EQ(problems[1].line, 3u);
}

TEST(MovingAiScenario, AcceptsVersionOnePointZeroAndSpaceSeparatedFields) {
  const auto problems = parseMovingAiScenario("version 1.0\n2 a.map 8 6 0 0 7 0 7\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].map, "a.map");
  EXPECT_EQ(problems[0].goal, (Cell{0, 7}));
  EXPECT_TRUE(parseMovingAiScenario("version 1\n").empty());
}

TEST(MovingAiScenario, BadLinesNameFileAndLine) {
  EXPECT_TRUE(has(parseError(""), {"s.scen: line 1:", "no 'version 1'"}));
  EXPECT_TRUE(has(parseError("0\ta.map\t8\t6\t0\t0\t7\t0\t7\n"), {"s.scen: line 1:", "expected the line 'version 1'"}));
  EXPECT_TRUE(has(parseError("version 2\n"), {"line 1:", "unknown scenario version '2'"}));
  EXPECT_TRUE(has(parseError("version 1\n0\ta.map\t8\t6\t0\t0\t7\t0\n"), {"line 2:", "expected 9 fields", "got 8"}));
  EXPECT_TRUE(has(parseError("version 1\n\n0\ta.map\t8\t6\t-1\t0\t7\t0\t7\n"), {"line 3:", "start x", "'-1'"}));
  EXPECT_TRUE(has(parseError("version 1\n0\ta.map\t8\t6\t0\t0\t7\ty\t7\n"), {"line 2:", "goal y", "'y'"}));
  EXPECT_TRUE(has(parseError("version 1\n0\ta.map\t8\t6\t0\t0\t7\t0\tnan\n"), {"line 2:", "optimal length"}));
  EXPECT_TRUE(has(parseError("version 1\n0\ta.map\t8\t6\t0\t0\t7\t0\t-3\n"), {"line 2:", "optimal length"}));
  EXPECT_TRUE(has(parseError("version 1\n0\t\t8\t6\t0\t0\t7\t0\t7\n"), {"line 2:", "map name is empty"}));
  EXPECT_TRUE(has(parseError("version 1\n0\ta.map\t8\t6\t0\t0\t7\t0\t7\t\t1\n"), {"line 2:", "got 11"}));
}

}  // namespace
}  // namespace eaci
