// The planning service's outcome -> Move Base Flex's mbf_msgs/GetPath code (src/ros/mbf_outcome.hpp):
// the table of docs/ros.md, every failure its own code, no failure a success (MBF reads < 10 as one).
#include <gtest/gtest.h>
#include <mbf_msgs/GetPathResult.h>

#include <set>

#include "mbf_outcome.hpp"

namespace {

using eaci_service::PlanOutcome;
using Result = mbf_msgs::GetPathResult;

TEST(MbfOutcome, Table) {
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kOk), Result::SUCCESS);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kStartOffMap), Result::OUT_OF_MAP);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kStartBlocked), Result::INVALID_START);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kGoalOffMap), Result::OUT_OF_MAP);  // a code executives know
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kGoalBlocked), Result::INVALID_GOAL);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kNoPath), Result::NO_PATH_FOUND);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kTimeLimit), Result::PAT_EXCEEDED);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kCancelled), Result::CANCELED);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kShutdown), Result::STOPPED);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kBadParameters), 72u);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kNotInitialised), Result::NOT_INITIALIZED);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kBadCostmap), Result::MAP_ERROR);
  EXPECT_EQ(eaci_ros::mbfOutcome(PlanOutcome::kInternalError), Result::INTERNAL_ERROR);
}

TEST(MbfOutcome, EveryFailureItsOwnErrorCodeButTheTwoEndsOffTheMap) {
  std::set<std::uint32_t> seen;
  for (int i = static_cast<int>(PlanOutcome::kOk); i <= static_cast<int>(PlanOutcome::kInternalError); ++i) {
    const auto outcome = static_cast<PlanOutcome>(i);
    const std::uint32_t code = eaci_ros::mbfOutcome(outcome);
    if (outcome != PlanOutcome::kGoalOffMap) EXPECT_TRUE(seen.insert(code).second) << "outcome " << i << " shares code " << code;
    if (outcome == PlanOutcome::kOk) continue;
    EXPECT_GE(code, 10u) << "outcome " << i << " would read as a success";
    // MBF's named errors are 50..63; 71..99 are the plugin's own.
    EXPECT_TRUE((code >= 50 && code <= 63) || (code >= 71 && code <= 99)) << "outcome " << i << ": " << code;
    EXPECT_NE(code, Result::FAILURE) << "FAILURE is for old, nav_core-based plugins";
  }
}

TEST(MbfOutcome, ValueOutsideTheEnumIsAnInternalError) {
  EXPECT_EQ(eaci_ros::mbfOutcome(static_cast<PlanOutcome>(1000)), Result::INTERNAL_ERROR);
}

}  // namespace
