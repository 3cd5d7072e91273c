// A perfect maze (one route between any two free cells) drawn by a randomized depth-first
// search (recursive backtracker, with an explicit stack) on a lattice of square maze cells:
// maze cell (i, j) is the free square of `corridor` x `corridor` grid cells whose top-left is
// (i * pitch, j * pitch), pitch = corridor + wall; between two neighbouring maze cells lies a
// wall `wall` cells thick, opened over the full corridor width where the search passed.
// Wall crossings stay occupied. The lattice has m = (size + wall) / pitch maze cells a side;
// rows and columns past m * pitch - wall are walls.
#pragma once

#include <cstdint>
#include <vector>

namespace eaci_bench {

struct MazeLayout {
  int size = 0;      // grid cells a side
  int corridor = 3;  // free width of a corridor, cells
  int wall = 1;      // wall thickness, cells
  int pitch() const { return corridor + wall; }
  int cellsPerSide() const { return (size + wall) / pitch(); }  // m
  int lastFree() const { return cellsPerSide() * pitch() - wall - 1; }  // last free row and column
};

// size * size values, row-major, eaci::kFreeValue or eaci::kOccupiedValue; the same for the
// same layout and seed. Requires cellsPerSide() >= 1.
std::vector<std::uint8_t> drawMaze(const MazeLayout& layout, std::uint64_t seed);

}  // namespace eaci_bench
