// Seeded test maps for the scale benchmark, start at the top-left corner, goal at the
// bottom-right, connected under the robot's move rule (no corner cutting):
//   rooms   - a grid of rooms 10-20 cells wide, separated by 1-cell walls with a 2-3 cell
//             door into every neighbouring room (both ranges: GeneratorOptions);
//   clutter - random rectangular blocks covering 20-30 % of the map, the corners kept free;
//   maze    - a perfect maze (drawMaze in map_generator.cpp) with corridors and walls of GeneratorOptions' widths;
//             the goal is the last free corner (bottom-right unless the size leaves a margin).
// A map whose start and goal are not connected (checked with A*) is drawn again with the
// next seed.
#pragma once

#include <cstdint>
#include <string>

#include "eaci/grid/cell.hpp"
#include "eaci/io/occupancy_map.hpp"

namespace eaci_bench {

enum class MapKind { kRooms, kClutter, kMaze };

const char* toString(MapKind kind);
bool parseMapKind(const std::string& text, MapKind& kind);

struct GeneratedMap {
  eaci::OccupancyMap map;
  MapKind kind = MapKind::kRooms;
  int size = 0;
  std::uint64_t seed = 0;       // the seed asked for
  std::uint64_t seed_used = 0;  // the seed that gave a connected map
  eaci::Cell start;
  eaci::Cell goal;
  double obstacle_fraction = 0.0;
  double optimum = 0.0;         // A* length, corner cutting forbidden
};

// What may differ from the scale benchmark's maps: wider doors for `costs`, whose inflation
// closes doors narrower than 3 cells, and building-like rooms and doors for `map` (e.g. rooms
// of 2-4 m and doors of 0.8-1 m at 0.05 m a cell: 40-80 and 16-20 cells).
struct GeneratorOptions {
  int door_min = 2;  // door widths, cells
  int door_max = 3;
  int room_min = 10;  // room widths between walls, cells
  int room_max = 20;
  int corridor = 3;   // maze: corridor width, cells
  int maze_wall = 1;  // maze: wall thickness, cells
};

// Empty when the options can be drawn from, else what is wrong with them (one sentence).
std::string generatorOptionsProblem(const GeneratorOptions& options);

// size x size cells. Throws std::runtime_error when 100 seeds in a row give no connected map.
GeneratedMap generateMap(MapKind kind, int size, std::uint64_t seed, const GeneratorOptions& options = {});

}  // namespace eaci_bench
