// eaci_bench map: one generated map (map_generator.hpp) written as a map_server map (trinary
// YAML + PGM), e.g. a building floor for move_base:
//   eaci_bench map --kind rooms --size 1200 --room-cells 40,80 --door-cells 16,20 --out /tmp/maps/building.yaml
#pragma once

#include <cstdint>
#include <string>

#include "map_generator.hpp"

namespace eaci_bench {

struct MapCommandOptions {
  MapKind kind = MapKind::kRooms;
  int size = 400;                // cells per side
  std::uint64_t seed = 1;
  GeneratorOptions generator;    // rooms: room and door widths (cells)
  double resolution = 0.05;      // m per cell; the origin is (0, 0)
  std::string out_yaml;          // the YAML; the PGM is written beside it
};

// The generated map with the options' resolution and origin (0, 0, 0).
eaci::OccupancyMap generatedMapInMetres(const MapCommandOptions& options, GeneratedMap& generated);

// Writes the map and prints what was written (size in cells and metres, seed used, obstacle
// fraction, the files). Returns the exit status (0).
int runMapCommand(const MapCommandOptions& options);

}  // namespace eaci_bench
