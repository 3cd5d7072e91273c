// Writing an occupancy map as a map_server map in trinary mode (YAML + binary PGM), so that a
// generated map can be served by map_server and read back by loadMapServerYaml with the same cells.
#pragma once

#include <string>

#include "eaci/io/occupancy_map.hpp"
#include "eaci/io/raw_map_writer.hpp"  // MapSaveError, SavedMapFiles

namespace eaci {

// Pixel values of the written image: map_server reads 0 as occupied, 254 as free and 205 as
// unknown under its default thresholds (occupied_thresh 0.65, free_thresh 0.196, negate 0).
constexpr std::uint8_t kOccupiedPixel = 0;
constexpr std::uint8_t kFreePixel = 254;
constexpr std::uint8_t kUnknownPixel = 205;

// Writes `map` (CellValues::kOccupancy: kFreeValue / kOccupiedValue / kUnknownValue) as
//   `yaml_path`: image, mode: trinary, resolution, origin [x, y, yaw] (numbers that read back
//                exactly), negate: 0, occupied_thresh: 0.65, free_thresh: 0.196;
//   the image:   a binary PGM (P5, maxval 255) beside it, named like it with the extension .pgm,
//                first row = top of the map, as map_server reads images.
// Throws MapSaveError naming the file when the map is empty or holds costs, its cell count is
// not width x height, a cell value is none of the three, the resolution is not positive and
// finite, the origin is not finite, or a file cannot be written.
SavedMapFiles saveTrinaryMap(const std::string& yaml_path, const OccupancyMap& map);

}  // namespace eaci
