// saveRawMap and saveTrinaryMap: map_server YAML (written by yaml-cpp's emitter) + binary PGM.
#include "eaci/io/map_server_writer.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "eaci/io/text.hpp"

namespace eaci {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw MapSaveError(oneLine("cannot save map " + path + ": " + reason));
}

void writeFile(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) fail(path, "cannot open the file for writing");
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) fail(path, "write error");
}

std::string rawPgmBytes(const GridView& cells) {
  std::string bytes = "P5\n" + std::to_string(cells.width()) + " " + std::to_string(cells.height()) + "\n255\n";
  bytes.reserve(bytes.size() + cells.cellCount());
  for (int r = 0; r < cells.height(); ++r)
    for (int c = 0; c < cells.width(); ++c) bytes.push_back(static_cast<char>(cells.value(Cell{r, c})));
  return bytes;
}

std::uint8_t pixelOf(std::uint8_t value, const std::string& yaml_path) {
  switch (value) {
    case kFreeValue: return kFreePixel;
    case kOccupiedValue: return kOccupiedPixel;
    case kUnknownValue: return kUnknownPixel;
    default: fail(yaml_path, "cell value " + std::to_string(value) + " is not free (0), occupied (100) or unknown (255)");
  }
}

std::string trinaryPgmBytes(const OccupancyMap& map, const std::string& yaml_path) {
  std::string bytes = "P5\n" + std::to_string(map.width) + " " + std::to_string(map.height) + "\n255\n";
  bytes.reserve(bytes.size() + map.cells.size());
  for (std::uint8_t value : map.cells) bytes.push_back(static_cast<char>(pixelOf(value, yaml_path)));  // row 0 = top
  return bytes;
}

// map_server's YAML: `comments` as '#' lines, then image, mode, resolution, origin (numbers that
// read back exactly), negate 0 and the default thresholds (map_server requires them).
std::string yamlText(const std::string& image_name, const char* mode, const MapFrame& frame,
                     const std::vector<std::string>& comments) {
  YAML::Emitter yaml;
  yaml << YAML::BeginMap;
  yaml << YAML::Key << "image" << YAML::Value << image_name;
  yaml << YAML::Key << "mode" << YAML::Value << mode;
  yaml << YAML::Key << "resolution" << YAML::Value << exactNumber(frame.resolution);
  yaml << YAML::Key << "origin" << YAML::Value << YAML::Flow << YAML::BeginSeq << exactNumber(frame.origin.x())
       << exactNumber(frame.origin.y()) << exactNumber(frame.origin_yaw) << YAML::EndSeq;
  yaml << YAML::Key << "negate" << YAML::Value << 0;
  yaml << YAML::Key << "occupied_thresh" << YAML::Value << "0.65";
  yaml << YAML::Key << "free_thresh" << YAML::Value << "0.196";
  yaml << YAML::EndMap;
  std::string text;
  for (const std::string& comment : comments) text += "# " + oneLine(comment) + "\n";
  return text + yaml.c_str() + "\n";
}

// Checks the frame, then writes the image (named like the YAML, extension .pgm) and the YAML.
SavedMapFiles writeMapFiles(const std::string& yaml_path, const MapFrame& frame, const std::string& pgm,
                            const char* mode, const std::vector<std::string>& comments) {
  if (!std::isfinite(frame.resolution) || !(frame.resolution > 0))
    fail(yaml_path, "resolution " + exactNumber(frame.resolution) + " is not a positive number");
  if (!frame.origin.allFinite() || !std::isfinite(frame.origin_yaw)) fail(yaml_path, "the origin is not finite");
  SavedMapFiles files;
  files.yaml_path = yaml_path;
  const fs::path image = fs::path(yaml_path).replace_extension(".pgm");
  if (image == fs::path(yaml_path)) fail(yaml_path, "the map file must not end in .pgm");
  files.image_path = image.string();
  writeFile(files.image_path, pgm);
  writeFile(yaml_path, yamlText(image.filename().string(), mode, frame, comments));
  return files;
}

}  // namespace

SavedMapFiles saveRawMap(const std::string& yaml_path, const GridView& cells, const MapFrame& frame,
                         const std::vector<std::string>& comment_lines) {
  if (cells.empty()) fail(yaml_path, "the grid has no cells");
  if (cells.width() != frame.width || cells.height() != frame.height) {
    fail(yaml_path, "the grid has " + std::to_string(cells.width()) + " x " + std::to_string(cells.height()) +
                        " cells, its frame " + std::to_string(frame.width) + " x " + std::to_string(frame.height));
  }
  return writeMapFiles(yaml_path, frame, rawPgmBytes(cells), "raw", comment_lines);
}

SavedMapFiles saveTrinaryMap(const std::string& yaml_path, const OccupancyMap& map) {
  if (map.width < 1 || map.height < 1) fail(yaml_path, "the map has no cells");
  if (map.values != CellValues::kOccupancy) fail(yaml_path, "the map holds costs, not occupancy (use saveRawMap)");
  if (map.cells.size() != static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height)) {
    fail(yaml_path, "the map has " + std::to_string(map.cells.size()) + " cells, not " + std::to_string(map.width) +
                        " x " + std::to_string(map.height));
  }
  if (!std::isfinite(map.resolution) || !(map.resolution > 0))
    fail(yaml_path, "resolution " + exactNumber(map.resolution) + " is not a positive number");
  return writeMapFiles(yaml_path, map, trinaryPgmBytes(map, yaml_path), "trinary", {});
}

}  // namespace eaci
