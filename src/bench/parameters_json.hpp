// Every solver parameter as JSON (from the library's one parameter table), and a map's cells as rows of 0 (free) / 1 (obstacle).
#pragma once

#include <nlohmann/json.hpp>

#include "eaci/aco/parameters.hpp"
#include "eaci/io/occupancy_map.hpp"

namespace eaci_bench {

nlohmann::json toJson(const eaci::Parameters& p);
nlohmann::json gridRows(const eaci::OccupancyMap& map);

}  // namespace eaci_bench
