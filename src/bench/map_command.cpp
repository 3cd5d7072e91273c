#include "map_command.hpp"

#include <filesystem>
#include <iomanip>
#include <iostream>

#include "eaci/io/map_server_writer.hpp"

namespace eaci_bench {

eaci::OccupancyMap generatedMapInMetres(const MapCommandOptions& options, GeneratedMap& generated) {
  generated = generateMap(options.kind, options.size, options.seed, options.generator);
  eaci::OccupancyMap map = generated.map;
  map.resolution = options.resolution;
  map.origin.setZero();
  map.origin_yaw = 0.0;
  return map;
}

int runMapCommand(const MapCommandOptions& options) {
  GeneratedMap generated;
  const eaci::OccupancyMap map = generatedMapInMetres(options, generated);
  const std::filesystem::path dir = std::filesystem::path(options.out_yaml).parent_path();
  if (!dir.empty()) std::filesystem::create_directories(dir);
  const eaci::SavedMapFiles files = eaci::saveTrinaryMap(options.out_yaml, map);
  const GeneratorOptions& g = options.generator;
  std::cout << toString(options.kind) << " " << map.width << " x " << map.height << " cells ("
            << std::fixed << std::setprecision(2) << map.width * map.resolution << " x "
            << map.height * map.resolution << " m at " << std::setprecision(3) << map.resolution << " m), seed "
            << generated.seed << " (used " << generated.seed_used << "), obstacles " << std::setprecision(1)
            << 100.0 * generated.obstacle_fraction << " %";
  if (options.kind == MapKind::kRooms)
    std::cout << ", rooms " << g.room_min << "-" << g.room_max << " cells, doors " << g.door_min << "-" << g.door_max
              << " cells";
  if (options.kind == MapKind::kMaze)
    std::cout << ", corridors " << g.corridor << " cells, walls " << g.maze_wall << " cells";
  std::cout << "\n" << files.yaml_path << "\n" << files.image_path << std::endl;
  return 0;
}

}  // namespace eaci_bench
