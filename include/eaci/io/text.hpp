// Text for messages and reports: a message on one line, a number without trailing zeros.
#pragma once

#include <string>

#include "eaci/number_text.hpp"  // formatNumber

namespace eaci {

// `text` on one line: line breaks and tabs become spaces, runs of spaces one space, and
// there is no space at either end ("" stays "").
std::string oneLine(const std::string& text);

// The shortest text that reads back as exactly `value` ("0.05", "-12.5", "1e-07"), for files
// that must round-trip: saved maps, parameter files.
std::string exactNumber(double value);

}  // namespace eaci
