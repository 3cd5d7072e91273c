// Writing a grid of costmap_2d costs as a map_server map in raw mode (YAML + binary PGM), so
// that a costmap a planner saw can be read back by loadMapServerYaml (and by map_server).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "eaci/grid/grid_view.hpp"
#include "eaci/grid/map_frame.hpp"

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

}  // namespace eaci
