// costmap_2d's cost values (costmap_2d/cost_values.h), the one copy of them for code without
// ROS headers: the core (inflation, unknown cells' price), the planning service, the adapters,
// the tools and the benchmarks.
#pragma once

#include <cstdint>

namespace eaci {

constexpr std::uint8_t kCostmapFree = 0;              // FREE_SPACE
constexpr std::uint8_t kCostmapDearestPassable = 252;  // INSCRIBED_INFLATED_OBSTACLE - 1: the dearest cost crossed
constexpr std::uint8_t kCostmapInscribed = 253;        // INSCRIBED_INFLATED_OBSTACLE
constexpr std::uint8_t kCostmapLethal = 254;           // LETHAL_OBSTACLE
constexpr std::uint8_t kCostmapUnknown = 255;          // NO_INFORMATION

}  // namespace eaci
