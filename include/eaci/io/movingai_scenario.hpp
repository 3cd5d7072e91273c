// MovingAI scenario files (.scen), the problems of the standard grid-pathfinding benchmarks
// (https://movingai.com/benchmarks/formats.html): a first line "version 1" (or "version 1.0"),
// then one problem per line, nine tab-separated fields:
//
//   bucket  map  map-width  map-height  start-x  start-y  goal-x  goal-y  optimal-length
//
// x is the column and y the row, both 0-based from the top-left corner; the optimal length is
// the octile distance (diagonal √2) without corner cutting, as movingai_map.hpp describes.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "eaci/grid/cell.hpp"

namespace eaci {

class ScenarioLoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ScenarioProblem {
  int bucket = 0;
  std::string map;          // the map file's name as written (usually relative to the .scen)
  int map_width = 0;
  int map_height = 0;
  Cell start;               // row = start-y, col = start-x
  Cell goal;
  double optimal_length = 0.0;
  std::size_t line = 0;     // 1-based line in the file (for messages)
};

// The problems in file order. Throws ScenarioLoadError ("<source_name>: line N: reason", one
// line) on a missing or unknown version line, a line that is not nine fields, or a field that
// is not a number of its kind (negative coordinates or sizes, a negative or non-finite length).
// Lines may end in "\r\n"; blank lines are skipped. Fields are split at tabs; a line without
// tabs is split at spaces.
std::vector<ScenarioProblem> parseMovingAiScenario(const std::string& text, const std::string& source_name = "<scen>");

// The file at `path` (at most 256 MiB), parsed by parseMovingAiScenario.
std::vector<ScenarioProblem> loadMovingAiScenario(const std::string& path);

}  // namespace eaci
