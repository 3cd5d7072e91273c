// MovingAI .map reader: header (type octile, height, width, map), then the rows.
#include "eaci/io/movingai_map.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "eaci/io/map_io.hpp"
#include "eaci/io/text.hpp"

namespace eaci {
namespace {

// Height and width above this are refused before anything is allocated (kMaxMapCells caps the product).
constexpr std::uint64_t kMaxSide = kMaxMapCells;

[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& reason) {
  throw MapLoadError(oneLine(source + ": line " + std::to_string(line) + ": " + reason));
}

// Splits the text into lines without their "\n" or "\r\n" (a final line without "\n" counts).
std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    begin = end + 1;
  }
  return lines;
}

// "key value" with one or more spaces or tabs between, none at the ends (trailing ones are allowed).
bool splitKeyValue(const std::string& line, std::string& key, std::string& value) {
  const std::size_t key_end = line.find_first_of(" \t");
  if (key_end == std::string::npos) return false;
  const std::size_t value_begin = line.find_first_not_of(" \t", key_end);
  if (value_begin == std::string::npos) return false;
  std::size_t value_end = line.find_last_not_of(" \t");
  key = line.substr(0, key_end);
  value = line.substr(value_begin, value_end + 1 - value_begin);
  return value.find_first_of(" \t") == std::string::npos;
}

std::string quoted(const std::string& text) { return "'" + (text.size() > 40 ? text.substr(0, 40) + "..." : text) + "'"; }

// A positive decimal integer, at most kMaxSide.
int parseSide(const std::string& value, const std::string& key, const std::string& source, std::size_t line) {
  std::uint64_t n = 0;
  for (char c : value) {
    if (c < '0' || c > '9') fail(source, line, key + " must be a positive whole number, got " + quoted(value));
    n = n * 10 + static_cast<std::uint64_t>(c - '0');
    if (n > kMaxSide) fail(source, line, key + " " + quoted(value) + " exceeds the limit of " + std::to_string(kMaxSide));
  }
  if (value.empty() || n == 0) fail(source, line, key + " must be a positive whole number, got " + quoted(value));
  return static_cast<int>(n);
}

struct Header {
  int height = 0;
  int width = 0;
  std::size_t first_row_index = 0;  // index into the lines
};

// The header lines (type, height, width in any order, each once), up to and including "map".
Header parseHeader(const std::vector<std::string>& lines, const std::string& source) {
  Header header;
  bool have_type = false;
  std::size_t k = 0;
  for (; k < lines.size(); ++k) {
    const std::size_t line = k + 1;
    std::string text = lines[k];
    text.erase(text.find_last_not_of(" \t") + 1);  // trailing spaces and tabs (npos + 1 = 0: all)
    if (text == "map") break;
    if (text.empty()) fail(source, line, "blank line in the header (expected type, height, width, map)");
    std::string key, value;
    if (!splitKeyValue(text, key, value)) {
      fail(source, line, "expected 'type octile', 'height H', 'width W' or 'map', got " + quoted(text));
    }
    if (key == "type") {
      if (have_type) fail(source, line, "type given twice");
      if (value != "octile") fail(source, line, "unknown map type " + quoted(value) + " (only octile is read)");
      have_type = true;
    } else if (key == "height") {
      if (header.height) fail(source, line, "height given twice");
      header.height = parseSide(value, "height", source, line);
    } else if (key == "width") {
      if (header.width) fail(source, line, "width given twice");
      header.width = parseSide(value, "width", source, line);
    } else {
      fail(source, line, "unknown header line " + quoted(text) + " (expected type, height, width, map)");
    }
  }
  const std::size_t line = std::min(k, lines.size()) + 1;
  if (k == lines.size()) fail(source, line, "header ends without the line 'map'");
  if (!have_type) fail(source, line, "header has no 'type octile' line");
  if (!header.height) fail(source, line, "header has no 'height H' line");
  if (!header.width) fail(source, line, "header has no 'width W' line");
  if (static_cast<std::uint64_t>(header.width) > kMaxMapCells / static_cast<std::uint64_t>(header.height)) {
    fail(source, line, "map of " + std::to_string(header.width) + " x " + std::to_string(header.height) +
                           " cells exceeds the limit of " + std::to_string(kMaxMapCells) + " cells");
  }
  header.first_row_index = k + 1;
  return header;
}

std::string describeChar(char c) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "byte 0x%02x", static_cast<unsigned char>(c));
  return hex;
}

}  // namespace

bool isMovingAiPassable(char c) { return c == '.' || c == 'G'; }

OccupancyMap parseMovingAiMap(const std::string& text, const std::string& source_name) {
  const std::vector<std::string> lines = splitLines(text);
  const Header header = parseHeader(lines, source_name);

  // The rows; trailing blank lines are allowed, anything else after the last row is not.
  std::size_t last = lines.size();
  while (last > header.first_row_index && lines[last - 1].empty()) --last;
  const std::size_t rows = last - header.first_row_index;
  if (rows != static_cast<std::size_t>(header.height)) {
    fail(source_name, rows < static_cast<std::size_t>(header.height) ? last + 1 : header.first_row_index + header.height + 1,
         "height " + std::to_string(header.height) + " but " + std::to_string(rows) + " rows");
  }

  OccupancyMap map;
  map.width = header.width;
  map.height = header.height;
  map.resolution = 1.0;
  map.cells.reserve(static_cast<std::size_t>(header.width) * static_cast<std::size_t>(header.height));
  for (std::size_t r = 0; r < rows; ++r) {
    const std::size_t line = header.first_row_index + r + 1;
    const std::string& row = lines[header.first_row_index + r];
    if (row.size() != static_cast<std::size_t>(header.width)) {
      fail(source_name, line, "row " + std::to_string(r) + " has " + std::to_string(row.size()) +
                                  " characters, width is " + std::to_string(header.width));
    }
    for (std::size_t c = 0; c < row.size(); ++c) {
      const auto byte = static_cast<unsigned char>(row[c]);
      if (byte < 0x21 || byte > 0x7e) {
        fail(source_name, line, describeChar(row[c]) + " in column " + std::to_string(c) +
                                    " (map cells are printable characters: '.' and 'G' passable, others blocked)");
      }
      map.cells.push_back(isMovingAiPassable(row[c]) ? kFreeValue : kOccupiedValue);
    }
  }
  return map;
}

}  // namespace eaci
