// A map's cells as JSON rows of 0 (free) / 1 (obstacle), for the plots.
#pragma once

#include <nlohmann/json.hpp>

#include "eaci/io/occupancy_map.hpp"

namespace eaci_bench {

nlohmann::json gridRows(const eaci::OccupancyMap& map);

}  // namespace eaci_bench
