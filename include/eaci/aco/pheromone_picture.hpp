// The pheromone as a picture of the map: per grid cell, the strongest pheromone leaving it.
#pragma once

#include <vector>

#include "eaci/aco/colony_region.hpp"
#include "eaci/aco/pheromone_field.hpp"

namespace eaci {

// Row-major over the whole grid; 0 on cells outside the colony's region (no pheromone there).
inline std::vector<double> strongestPheromoneByGridCell(const PheromoneField& field, const ColonyRegion& region) {
  std::vector<double> picture(region.gridCellCount(), 0.0);
  for (std::uint32_t r = 0; r < region.size() && r < field.cellCount(); ++r)
    picture[region.gridIndex(r)] = field.strongestFrom(r);
  return picture;
}

}  // namespace eaci
