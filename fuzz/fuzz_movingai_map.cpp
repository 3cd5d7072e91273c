// parseMovingAiMap (MovingAI .map): either a well-formed map of free / occupied cells or a
// one-line MapLoadError naming the source. A parsed map, written back as a .map ('.' free,
// '@' blocked), parses to the same map.
#include <cstdint>
#include <string>

#include "eaci/io/map_io.hpp"
#include "eaci/io/movingai_map.hpp"
#include "eaci/io/occupancy_map.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string source = "fuzz.map";
  eaci::OccupancyMap map;
  try {
    map = eaci::parseMovingAiMap(eaci::fuzz::asString(data, size), source);
  } catch (const eaci::MapLoadError& error) {
    eaci::fuzz::checkMapErrorMessage(error.what(), source);
    return 0;
  }
  FUZZ_CHECK(map.width >= 1 && map.height >= 1);
  FUZZ_CHECK(map.cells.size() == static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height));
  FUZZ_CHECK(map.cells.size() <= eaci::kMaxMapCells);
  FUZZ_CHECK(map.resolution == 1.0 && map.origin == Eigen::Vector2d::Zero());
  std::string text = "type octile\nheight " + std::to_string(map.height) + "\nwidth " + std::to_string(map.width) + "\nmap\n";
  for (std::size_t i = 0; i < map.cells.size(); ++i) {
    FUZZ_CHECK(map.cells[i] == eaci::kFreeValue || map.cells[i] == eaci::kOccupiedValue);
    text += map.cells[i] == eaci::kFreeValue ? '.' : '@';
    if ((i + 1) % static_cast<std::size_t>(map.width) == 0) text += '\n';
  }
  const eaci::OccupancyMap again = eaci::parseMovingAiMap(text, source);
  FUZZ_CHECK(again.width == map.width && again.height == map.height && again.cells == map.cells);
  return 0;
}
