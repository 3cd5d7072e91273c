// The planning service's outcome as Move Base Flex's mbf_msgs/GetPath result code: one pure
// function, used by the MBF planner plugin (eaci_costmap_planner.hpp) and tested on its own
// (test/ros/test_mbf_outcome.cpp). The table is in docs/ros.md ("Move Base Flex").
#pragma once

#include <cstdint>

#include "plan_outcome.hpp"

namespace eaci_ros {

// A plugin-specific code (mbf_msgs/GetPath reserves 71..99 for them) where MBF 0.4 has no name.
constexpr std::uint32_t kMbfBadParameters = 72;   // the planner's parameters in force are refused

// SUCCESS for kOk; every failure a code of its own (named mbf_msgs::GetPathResult constants, or
// the one above) but the two ends off the map, both OUT_OF_MAP as MBF's own planners give them
// (the message names which): start blocked INVALID_START,
// goal blocked INVALID_GOAL, no path NO_PATH_FOUND, time limit PAT_EXCEEDED, cancelled
// CANCELED, shutdown STOPPED, bad parameters 72, not initialised NOT_INITIALIZED, bad costmap
// MAP_ERROR, internal error (and any value outside the enum) INTERNAL_ERROR.
std::uint32_t mbfOutcome(eaci_service::PlanOutcome outcome) noexcept;

}  // namespace eaci_ros
