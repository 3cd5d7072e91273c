// MovingAI .scen reader: "version 1", then nine fields per problem.
#include "eaci/io/movingai_scenario.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "eaci/io/text.hpp"

namespace eaci {
namespace {

constexpr std::size_t kMaxScenarioFileBytes = std::size_t{1} << 28;  // 256 MiB
constexpr std::int64_t kMaxCoordinate = std::int64_t{1} << 30;

[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& reason) {
  throw ScenarioLoadError(oneLine(source + ": line " + std::to_string(line) + ": " + reason));
}

std::string quoted(const std::string& text) { return "'" + (text.size() > 40 ? text.substr(0, 40) + "..." : text) + "'"; }

std::string trimmed(const std::string& text) {
  const std::size_t begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t") + 1 - begin);
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  if (line.find('\t') != std::string::npos) {
    std::size_t begin = 0;
    while (true) {
      const std::size_t end = line.find('\t', begin);
      fields.push_back(trimmed(line.substr(begin, end == std::string::npos ? std::string::npos : end - begin)));
      if (end == std::string::npos) break;
      begin = end + 1;
    }
    while (fields.size() > 9 && fields.back().empty()) fields.pop_back();  // trailing tabs
  } else {
    std::istringstream words(line);
    for (std::string word; words >> word;) fields.push_back(word);
  }
  return fields;
}

// A whole number 0..kMaxCoordinate (bucket, sizes, coordinates).
int parseCount(const std::string& field, const char* what, const std::string& source, std::size_t line) {
  std::int64_t n = 0;
  for (char c : field) {
    if (c < '0' || c > '9') fail(source, line, std::string(what) + " must be a whole number >= 0, got " + quoted(field));
    n = n * 10 + (c - '0');
    if (n > kMaxCoordinate) fail(source, line, std::string(what) + " " + quoted(field) + " is too large");
  }
  if (field.empty()) fail(source, line, std::string(what) + " is empty");
  return static_cast<int>(n);
}

double parseLength(const std::string& field, const std::string& source, std::size_t line) {
  const bool plain = !field.empty() && field.find_first_not_of("0123456789.eE+-") == std::string::npos;
  errno = 0;
  char* end = nullptr;
  const double value = plain ? std::strtod(field.c_str(), &end) : 0.0;
  if (!plain || end != field.c_str() + field.size() || errno == ERANGE || !std::isfinite(value) || value < 0) {
    fail(source, line, "optimal length must be a number >= 0, got " + quoted(field));
  }
  return value;
}

}  // namespace

std::vector<ScenarioProblem> parseMovingAiScenario(const std::string& text, const std::string& source_name) {
  std::vector<ScenarioProblem> problems;
  bool have_version = false;
  std::size_t line = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string content = text.substr(begin, end - begin);
    begin = end + 1;
    ++line;
    if (!content.empty() && content.back() == '\r') content.pop_back();
    if (trimmed(content).empty()) continue;
    if (!have_version) {
      std::istringstream words(content);
      std::string key, version, rest;
      words >> key >> version;
      if (key != "version" || (words >> rest)) {
        fail(source_name, line, "expected the line 'version 1', got " + quoted(content));
      }
      if (version != "1" && version != "1.0") fail(source_name, line, "unknown scenario version " + quoted(version) + " (1 is read)");
      have_version = true;
      continue;
    }
    const std::vector<std::string> fields = splitFields(content);
    if (fields.size() != 9) {
      fail(source_name, line, "expected 9 fields (bucket, map, width, height, start x, start y, goal x, goal y, "
                              "optimal length), got " + std::to_string(fields.size()));
    }
    ScenarioProblem p;
    p.line = line;
    p.bucket = parseCount(fields[0], "bucket", source_name, line);
    if (fields[1].empty()) fail(source_name, line, "map name is empty");
    p.map = fields[1];
    p.map_width = parseCount(fields[2], "map width", source_name, line);
    p.map_height = parseCount(fields[3], "map height", source_name, line);
    p.start.col = parseCount(fields[4], "start x", source_name, line);
    p.start.row = parseCount(fields[5], "start y", source_name, line);
    p.goal.col = parseCount(fields[6], "goal x", source_name, line);
    p.goal.row = parseCount(fields[7], "goal y", source_name, line);
    p.optimal_length = parseLength(fields[8], source_name, line);
    problems.push_back(std::move(p));
  }
  if (!have_version) fail(source_name, line + 1, "empty scenario: no 'version 1' line");
  return problems;
}

std::vector<ScenarioProblem> loadMovingAiScenario(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioLoadError(oneLine("cannot open " + path));
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    if (static_cast<std::size_t>(in.gcount()) > kMaxScenarioFileBytes - text.size())
      throw ScenarioLoadError(oneLine(path + ": file is larger than the limit of " + std::to_string(kMaxScenarioFileBytes) + " bytes"));
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
  }
  return parseMovingAiScenario(text, path);
}

}  // namespace eaci
