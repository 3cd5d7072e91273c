// parseMapServerYaml (map_server YAML + its image), the text loadMapServerYaml reads from disk.
// The input is the YAML text, optionally followed by a NUL byte and the bytes of the image it
// names (without one, the image is a fixed 3 x 2 PGM). No file is read: the image comes from
// the input whatever path the YAML gives. Either a well-formed map or a one-line MapLoadError
// that names the YAML file (mode: raw gives cells of any value, trinary free / occupied / unknown).
#include <cmath>
#include <cstdint>
#include <string>

#include "eaci/io/map_io.hpp"
#include "eaci/io/occupancy_map.hpp"
#include "fuzz_check.hpp"

namespace {
const std::string kDefaultImage = std::string("P5\n3 2\n255\n") + std::string("\x00\x80\xfe\xff\xcd\x10", 6);
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string source = "/fuzz/maps/map.yaml";
  const std::string input = eaci::fuzz::asString(data, size);
  const std::size_t nul = input.find('\0');
  const std::string yaml = input.substr(0, nul);
  const std::string image = nul == std::string::npos ? kDefaultImage : input.substr(nul + 1);

  bool image_read = false;
  eaci::OccupancyMap map;
  try {
    map = eaci::parseMapServerYaml(yaml, source, [&](const std::string& image_path) {
      FUZZ_CHECK(!image_path.empty());
      image_read = true;
      return image;
    });
  } catch (const eaci::MapLoadError& error) {
    eaci::fuzz::checkMapErrorMessage(error.what(), source);
    return 0;
  }
  FUZZ_CHECK(image_read);
  FUZZ_CHECK(map.width >= 1 && map.height >= 1);
  FUZZ_CHECK(map.cells.size() == static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height));
  FUZZ_CHECK(std::isfinite(map.resolution) && map.resolution > 0.0);
  FUZZ_CHECK(map.origin.allFinite() && std::isfinite(map.origin_yaw));
  // mode: raw keeps every pixel (a costmap_2d cost, any byte); trinary gives three values only.
  if (map.values == eaci::CellValues::kOccupancy) {
    for (const std::uint8_t cell : map.cells) {
      FUZZ_CHECK(cell == eaci::kFreeValue || cell == eaci::kOccupiedValue || cell == eaci::kUnknownValue);
    }
  }
  return 0;
}
