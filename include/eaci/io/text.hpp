// Text for messages and reports: a message on one line, a number without trailing zeros.
#pragma once

#include <string>

namespace eaci {

// `text` on one line: line breaks and tabs become spaces, runs of spaces one space, and
// there is no space at either end ("" stays "").
std::string oneLine(const std::string& text);

// `value` with at most `max_decimals` decimals and no trailing zeros: "0.05", "20", "33.3137".
std::string formatNumber(double value, int max_decimals = 4);

// The shortest text that reads back as exactly `value` ("0.05", "-12.5", "1e-07"), for files
// that must round-trip: saved maps, parameter files.
std::string exactNumber(double value);

}  // namespace eaci
