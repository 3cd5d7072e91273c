// Tests of the MovingAI .map reader (include/eaci/io/movingai_map.hpp) on small hand-written maps.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "eaci/io/map_io.hpp"
#include "eaci/io/movingai_map.hpp"
#include "test_support.hpp"

namespace eaci {
namespace {

namespace fs = std::filesystem;

using namespace std::string_literals;

constexpr std::uint8_t F = kFreeValue;
constexpr std::uint8_t O = kOccupiedValue;

std::string parseError(const std::string& text, const std::string& source = "m.map") {
  try {
    parseMovingAiMap(text, source);
  } catch (const MapLoadError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected a MapLoadError for:\n" << text;
  return "";
}

::testing::AssertionResult has(const std::string& message, std::initializer_list<std::string> parts) {
  return eaci::test::isOneLineWith(message, parts);
}

TEST(MovingAiMap, ParsesHeaderAndRowsTopFirst) {
  // 3 wide, 2 high: row 0 ". @ .", row 1 "G T .".
  const OccupancyMap map = parseMovingAiMap("type octile\nheight 2\nwidth 3\nmap\n.@.\nGT.\n");
  EXPECT_EQ(map.width, 3);
  EXPECT_EQ(map.height, 2);
  EXPECT_EQ(map.resolution, 1.0);
  EXPECT_EQ(map.origin.x(), 0.0);
  EXPECT_EQ(map.origin.y(), 0.0);
  EXPECT_EQ(map.values, CellValues::kOccupancy);
  EXPECT_EQ(map.cells, (std::vector<std::uint8_t>{F, O, F, F, O, F}));
}

TEST(MovingAiMap, OnlyDotAndGArePassable) {
  EXPECT_TRUE(isMovingAiPassable('.'));
  EXPECT_TRUE(isMovingAiPassable('G'));
  for (char c : {'@', 'O', 'T', 'S', 'W', 'g', 'x', '#', '0', '1'}) EXPECT_FALSE(isMovingAiPassable(c)) << c;
  // Every printable character in one row: exactly two cells free.
  std::string row;
  for (char c = '!'; c <= '~'; ++c) row += c;
  const OccupancyMap map = parseMovingAiMap("type octile\nheight 1\nwidth " + std::to_string(row.size()) + "\nmap\n" + row + "\n");
  ASSERT_EQ(map.cells.size(), row.size());
  int free_cells = 0;
  for (std::size_t k = 0; k < row.size(); ++k) {
    const bool free_cell = map.cells[k] == F;
    free_cells += free_cell;
    EXPECT_EQ(free_cell, row[k] == '.' || row[k] == 'G') << row[k];
    EXPECT_TRUE(map.cells[k] == F || map.cells[k] == O);
  }
  EXPECT_EQ(free_cells, 2);
}

TEST(MovingAiMap, AcceptsCrLfTrailingBlankLinesAndHeaderInAnyOrder) {
  const OccupancyMap a = parseMovingAiMap("type octile\r\nheight 2\r\nwidth 2\r\nmap\r\n.@\r\n@.\r\n\r\n\n");
  EXPECT_EQ(a.cells, (std::vector<std::uint8_t>{F, O, O, F}));
  const OccupancyMap b = parseMovingAiMap("width 2\nheight 2\ntype  octile \nmap\n.@\n@.");  // no final newline
  EXPECT_EQ(b.cells, a.cells);
  EXPECT_EQ(b.width, 2);
  EXPECT_EQ(b.height, 2);
}

TEST(MovingAiMap, BadHeadersNameFileAndLine) {
  EXPECT_TRUE(has(parseError("type tile\nheight 1\nwidth 1\nmap\n.\n"), {"m.map: line 1:", "unknown map type 'tile'"}));
  EXPECT_TRUE(has(parseError("type octile\nheight x\nwidth 1\nmap\n.\n"), {"m.map: line 2:", "height", "'x'"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 1\nwidth 0\nmap\n.\n"), {"line 3:", "width", "positive"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 1\nwidth -1\nmap\n.\n"), {"line 3:", "width"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 1\nheight 1\nwidth 1\nmap\n.\n"), {"line 3:", "height given twice"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 1\nwidth 1\ncolour red\nmap\n.\n"), {"line 4:", "unknown header line"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 1\nwidth 1\n"), {"line 4:", "without the line 'map'"}));
  EXPECT_TRUE(has(parseError("height 1\nwidth 1\nmap\n.\n"), {"line 3:", "no 'type octile'"}));
  EXPECT_TRUE(has(parseError("type octile\nwidth 1\nmap\n.\n"), {"line 3:", "no 'height H'"}));
  EXPECT_TRUE(has(parseError(""), {"m.map: line 1:", "without the line 'map'"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 99999999999\nwidth 1\nmap\n"), {"line 2:", "exceeds the limit"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 65536\nwidth 65536\nmap\n"), {"line 4:", "exceeds the limit"}));
}

TEST(MovingAiMap, WrongRowCountOrWidthNamesTheLine) {
  // Header lines 1-4, rows from line 5.
  EXPECT_TRUE(has(parseError("type octile\nheight 3\nwidth 2\nmap\n..\n..\n"), {"line 7:", "height 3 but 2 rows"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 1\nwidth 2\nmap\n..\n..\n"), {"line 6:", "height 1 but 2 rows"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 2\nwidth 2\nmap\n..\n...\n"), {"line 6:", "row 1 has 3 characters, width is 2"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 2\nwidth 2\nmap\n.\n..\n"), {"line 5:", "row 0 has 1 characters"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 2\nwidth 2\nmap\n..\n\n..\n"), {"line 7:", "height 2 but 3 rows"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 3\nwidth 2\nmap\n..\n\n..\n"), {"line 6:", "row 1 has 0 characters"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 1\nwidth 2\nmap\n. \n"), {"line 5:", "byte 0x20 in column 1"}));
  EXPECT_TRUE(has(parseError("type octile\nheight 1\nwidth 2\nmap\n.\0\n"s), {"line 5:", "byte 0x00"}));
}

TEST(MovingAiMap, LoadMapDispatchesOnTheExtension) {
  const fs::path dir = fs::temp_directory_path() / ("eaci_movingai_" + std::to_string(static_cast<long>(::getpid())));
  fs::create_directories(dir);
  const fs::path path = dir / "tiny.MAP";
  std::ofstream(path) << "type octile\nheight 1\nwidth 3\nmap\n.T.\n";
  const OccupancyMap map = loadMap(path.string());
  EXPECT_EQ(map.cells, (std::vector<std::uint8_t>{F, O, F}));
  std::ofstream(path) << "type octile\nheight 2\nwidth 3\nmap\n.T.\n";
  try {
    loadMap(path.string());
    ADD_FAILURE() << "expected a MapLoadError";
  } catch (const MapLoadError& error) {
    EXPECT_TRUE(has(error.what(), {path.string() + ": line 6:", "height 2 but 1 rows"}));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace eaci
