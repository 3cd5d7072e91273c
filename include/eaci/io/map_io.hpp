// Reading maps: map_server YAML + image (PGM P5/P2, PNG), plain 0/1 matrices, and MovingAI
// benchmark maps (.map, movingai_map.hpp).
//
// Every reader either returns a well-formed OccupancyMap (width, height >= 1,
// cells.size() == width * height, resolution > 0 and finite) or throws
// MapLoadError with a one-line reason that names the file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "eaci/io/occupancy_map.hpp"

namespace eaci {

class MapLoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Largest map the readers accept (cells). Larger inputs are refused before allocation.
constexpr std::size_t kMaxMapCells = std::size_t{1} << 26;  // 67,108,864 cells, e.g. 8192 x 8192

// Largest file the readers read (bytes): enough for a maximal 16-bit P5 image. Larger files
// are refused, and reading stops there, so a huge or endless input cannot exhaust memory.
constexpr std::size_t kMaxMapFileBytes = std::size_t{4} * kMaxMapCells;  // 256 MiB

// Dispatches on the extension (any case): .yaml / .yml -> map_server map, .map -> MovingAI
// benchmark map (movingai_map.hpp), anything else -> 0/1 matrix.
OccupancyMap loadMap(const std::string& path);

// map_server map: image, resolution, origin, negate, occupied_thresh, free_thresh, mode.
// mode trinary (the default): the image thresholded (thresholdImage), CellValues::kOccupancy.
// mode raw: each pixel as it is (decodeRawImage) is a costmap_2d cost, CellValues::kCostmapCosts;
// the thresholds are not used, negate is (as in map_server). mode scale and any other value
// are refused with a MapLoadError naming the file and the value.
OccupancyMap loadMapServerYaml(const std::string& yaml_path);

// The same from the YAML text, as if read from the file yaml_path (errors name it, and a
// relative image path is resolved against its directory). read_image returns the bytes of
// the image at a resolved path; by default the image is read from disk (used by the fuzzer).
using ImageFileReader = std::function<std::string(const std::string& image_path)>;
OccupancyMap parseMapServerYaml(const std::string& yaml_text, const std::string& yaml_path,
                                const ImageFileReader& read_image = nullptr);

// Text matrix of 0 (free) and 1 (obstacle), first line = top row. Cells separated by
// spaces, tabs or commas, or written without separators ("0110"). Resolution 1, origin 0.
OccupancyMap loadMatrixText(const std::string& path);
OccupancyMap parseMatrixText(const std::string& text, const std::string& source_name = "<text>");

// A grayscale image decoded to 0..255 per pixel (row 0 = top).
struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;
};

// PGM, binary (P5) or ASCII (P2), 8 or 16 bit (16-bit values are scaled to 0..255).
GrayImage parsePgm(const std::string& bytes, const std::string& source_name = "<pgm>");

// Any map image: PGM P2/P5 by parsePgm; PNG, BMP and GIF by stb_image, converted to
// 8-bit grey. Identified by content, not by file name; other formats are refused.
GrayImage decodeImage(const std::string& bytes, const std::string& source_name = "<image>");

// map_server's raw mode (image_loader.cpp): a pixel's value is the mean of its colour channels
// (alpha not counted), 255 minus that with `negate`, truncated to a byte. Only images whose
// bytes are the values are read: 8-bit PGM (maxval 255) and PNG of 8 bits per channel without
// a palette; any other image is refused (a scaled or palette image would give other values).
GrayImage decodeRawImage(const std::string& bytes, bool negate, const std::string& source_name = "<image>");

// map_server's modes that this reader knows (map_server's third, scale, is refused).
enum class MapServerMode { kTrinary, kRaw };

// map_server's thresholding of one image (trinary mode): p = (255 - v) / 255, or v / 255 with
// negate; p > occupied_thresh -> occupied, p < free_thresh -> free, else unknown.
struct MapServerThresholds {
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
};
std::vector<std::uint8_t> thresholdImage(const GrayImage& image, const MapServerThresholds& thresholds);

}  // namespace eaci
