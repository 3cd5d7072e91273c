#include "eaci/io/text.hpp"

#include <charconv>
#include <iomanip>
#include <sstream>

namespace eaci {

std::string oneLine(const std::string& text) {
  std::string out;
  bool space = false;
  for (char ch : text) {
    if (ch == '\n' || ch == '\r' || ch == '\t') ch = ' ';
    if (ch == ' ' && (space || out.empty())) continue;
    space = ch == ' ';
    out += ch;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::string exactNumber(double value) {
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

}  // namespace eaci
