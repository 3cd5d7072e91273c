// parsePgm (PGM P2/P5, 8 and 16 bit): either a well-formed image or a one-line MapLoadError.
// A decoded image, written back as an 8-bit P5, must decode to the same pixels.
#include <cstdint>
#include <string>

#include "eaci/io/map_io.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string source = "fuzz.pgm";
  const std::string bytes = eaci::fuzz::asString(data, size);
  eaci::GrayImage image;
  try {
    image = eaci::parsePgm(bytes, source);
  } catch (const eaci::MapLoadError& error) {
    eaci::fuzz::checkMapErrorMessage(error.what(), source);
    return 0;
  }
  eaci::fuzz::checkWellFormedImage(image);

  // decodeImage dispatches PGM to the same parser.
  FUZZ_CHECK(eaci::decodeImage(bytes, source).pixels == image.pixels);

  const std::string p5 = "P5\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n" +
                         std::string(image.pixels.begin(), image.pixels.end());
  const eaci::GrayImage again = eaci::parsePgm(p5, source);
  FUZZ_CHECK(again.width == image.width && again.height == image.height && again.pixels == image.pixels);
  return 0;
}
