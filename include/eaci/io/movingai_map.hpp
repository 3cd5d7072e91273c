// MovingAI grid maps (.map), the format of the standard grid-pathfinding benchmarks
// (Sturtevant 2012, https://movingai.com/benchmarks/formats.html):
//
//   type octile
//   height H
//   width W
//   map
//   <H rows of W characters, row 0 = top>
//
// '.' and 'G' are passable, every other printable character ('@', 'O', 'T', 'S', 'W', ...)
// is an obstacle. The benchmarks' octile moves (diagonal √2, no corner cutting: a diagonal
// needs both side cells passable) are the planners' rule with allow_corner_cutting = false.
// A cell at MovingAI (x, y) is the cell row y, column x.
#pragma once

#include <string>

#include "eaci/io/occupancy_map.hpp"

namespace eaci {

// True for the characters the benchmarks' octile maps count as passable: '.' and 'G'.
bool isMovingAiPassable(char c);

// The map text -> an occupancy map (kFreeValue / kOccupiedValue), resolution 1, origin 0.
// Throws MapLoadError ("<source_name>: line N: reason", one line) on a bad or missing header
// line, a type other than octile, a size out of range, a wrong number of rows, a row of the
// wrong width, or a control or non-ASCII byte in a row. Lines may end in "\r\n"; blank lines
// after the last row are ignored.
OccupancyMap parseMovingAiMap(const std::string& text, const std::string& source_name = "<map>");

// The file at `path` (at most kMaxMapFileBytes), parsed by parseMovingAiMap.
OccupancyMap loadMovingAiMap(const std::string& path);

}  // namespace eaci
