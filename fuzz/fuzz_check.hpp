// Helpers shared by the fuzz targets: a check that survives NDEBUG and stops the run with a
// readable reason (libFuzzer then saves the input as a crash artifact).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "eaci/io/map_io.hpp"

#define FUZZ_CHECK(condition)                                                                     \
  do {                                                                                            \
    if (!(condition)) {                                                                           \
      std::fprintf(stderr, "%s:%d: FUZZ_CHECK failed: %s\n", __FILE__, __LINE__, #condition);     \
      std::abort();                                                                               \
    }                                                                                             \
  } while (false)

namespace eaci::fuzz {

inline std::string asString(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// The readers' contract: one line, naming the source first ("<source>: reason").
inline void checkMapErrorMessage(const std::string& message, const std::string& source) {
  FUZZ_CHECK(!message.empty());
  FUZZ_CHECK(message.find('\n') == std::string::npos);
  FUZZ_CHECK(message.find('\r') == std::string::npos);
  FUZZ_CHECK(message.compare(0, source.size() + 2, source + ": ") == 0);
}

// A decoded image: at least 1 x 1, within the cell cap, one pixel per cell.
inline void checkWellFormedImage(const eaci::GrayImage& image) {
  FUZZ_CHECK(image.width >= 1 && image.height >= 1);
  FUZZ_CHECK(static_cast<std::uint64_t>(image.width) * static_cast<std::uint64_t>(image.height) <= eaci::kMaxMapCells);
  FUZZ_CHECK(image.pixels.size() == static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
}

}  // namespace eaci::fuzz
