// Writing a map as a map_server map (YAML + binary PGM): the costs a planner saw in raw mode, so
// that a costmap can be replayed offline, and an occupancy map in trinary mode, so that a
// generated map can be served by map_server. Both read back with loadMapServerYaml unchanged.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/map_frame.hpp"
#include "eaci/io/occupancy_map.hpp"

namespace eaci {

class MapSaveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SavedMapFiles {
  std::string yaml_path;
  std::string image_path;
};

// Writes the raw byte of every cell of `cells` (GridView::value, whatever the buffer's row
// order; costmap_2d: 0 free, 1..252 cost, 253 / 254 obstacle, 255 unknown) as a map_server map:
//   `yaml_path`: `comment_lines` as '#' comments (one line each), then image, mode: raw,
//                resolution, origin [x, y, yaw] (numbers that read back exactly), negate: 0,
//                occupied_thresh: 0.65, free_thresh: 0.196 (map_server requires them; raw mode
//                does not use the thresholds);
//   the image:   a binary PGM (P5, maxval 255) beside it, named like it with the extension .pgm,
//                first row = top of the map (the row farthest from the origin), as map_server
//                reads images.
// `frame` gives the resolution and origin; its width and height must be the view's. Throws
// MapSaveError naming the file when the view is empty, the sizes differ, the resolution is not
// positive and finite, the origin is not finite, or a file cannot be written.
SavedMapFiles saveRawMap(const std::string& yaml_path, const GridView& cells, const MapFrame& frame,
                         const std::vector<std::string>& comment_lines = {});

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
