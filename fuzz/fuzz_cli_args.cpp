// The CLI's argument parsers (src/tools/cli_args.hpp): "R,C" (--start/--goal), "X,Y"
// (--start-xy/--goal-xy), serial numbers (--start-cell/--goal-cell) and "key=value" (--set).
// Every parser gets the whole input; each either returns a value or throws
// std::invalid_argument. A parsed value formats back to text that parses to the same value.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cli_args.hpp"
#include "fuzz_check.hpp"

namespace {

bool isTrimmed(const std::string& s) {
  const std::string space = " \t\r\n";
  return s.empty() || (space.find(s.front()) == std::string::npos && space.find(s.back()) == std::string::npos);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace cli = eaci::cli;
  const std::string text = eaci::fuzz::asString(data, size);

  const std::string trimmed = cli::trim(text);
  FUZZ_CHECK(isTrimmed(trimmed));
  FUZZ_CHECK(cli::trim(trimmed) == trimmed);
  FUZZ_CHECK(trimmed.empty() || text.find(trimmed) != std::string::npos);

  try {
    const eaci::Cell cell = cli::parseRowCol(text, "--start");
    const eaci::Cell again = cli::parseRowCol(std::to_string(cell.row) + "," + std::to_string(cell.col), "--start");
    FUZZ_CHECK(again.row == cell.row && again.col == cell.col);
  } catch (const std::invalid_argument& error) {
    FUZZ_CHECK(std::string(error.what()).rfind("--start: ", 0) == 0);
  }

  try {
    const auto [x, y] = cli::parseXY(text, "--start-xy");
    FUZZ_CHECK(std::isfinite(x) && std::isfinite(y));
    char formatted[128];
    std::snprintf(formatted, sizeof formatted, "%.17g,%.17g", x, y);
    const auto [x2, y2] = cli::parseXY(formatted, "--start-xy");
    FUZZ_CHECK(x2 == x && y2 == y);
  } catch (const std::invalid_argument& error) {
    FUZZ_CHECK(std::string(error.what()).rfind("--start-xy: ", 0) == 0);
  }

  try {
    const std::int64_t serial = cli::parseSerial(text, "--start-cell");
    FUZZ_CHECK(cli::parseSerial(std::to_string(serial), "--start-cell") == serial);
  } catch (const std::invalid_argument& error) {
    FUZZ_CHECK(std::string(error.what()).rfind("--start-cell: ", 0) == 0);
  }

  try {
    const auto [key, value] = cli::splitAssignment(text, "--set");
    FUZZ_CHECK(!key.empty() && key.find('=') == std::string::npos);
    FUZZ_CHECK(isTrimmed(key) && isTrimmed(value));
  } catch (const std::invalid_argument& error) {
    FUZZ_CHECK(std::string(error.what()).rfind("--set: ", 0) == 0);
  }
  return 0;
}
