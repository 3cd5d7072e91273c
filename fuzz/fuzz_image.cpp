// decodeImage: PGM by the own parser, PNG / BMP / GIF by stb_image (an instrumented copy of
// Debian's stb_image.h, see stb_image_impl.cpp), anything else refused. Either a well-formed
// image or a one-line MapLoadError; the map_server thresholding of a decoded image yields
// only free / occupied / unknown cells.
#include <cstdint>
#include <string>

#include "eaci/io/map_io.hpp"
#include "eaci/io/occupancy_map.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string source = "fuzz.img";
  eaci::GrayImage image;
  try {
    image = eaci::decodeImage(eaci::fuzz::asString(data, size), source);
  } catch (const eaci::MapLoadError& error) {
    eaci::fuzz::checkMapErrorMessage(error.what(), source);
    return 0;
  }
  eaci::fuzz::checkWellFormedImage(image);

  eaci::MapServerThresholds thresholds;
  thresholds.negate = size % 2 == 1;
  const std::vector<std::uint8_t> cells = eaci::thresholdImage(image, thresholds);
  FUZZ_CHECK(cells.size() == image.pixels.size());
  for (const std::uint8_t cell : cells) {
    FUZZ_CHECK(cell == eaci::kFreeValue || cell == eaci::kOccupiedValue || cell == eaci::kUnknownValue);
  }
  return 0;
}
