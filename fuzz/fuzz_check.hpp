// Helpers shared by the fuzz targets: a check that survives NDEBUG and stops the run with a
// readable reason (libFuzzer then saves the input as a crash artifact).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

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

}  // namespace eaci::fuzz
