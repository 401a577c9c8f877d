// F(K, Pi): which propositional regions the robot can never reach, and why.

#include "physltl/knowledge/feasibility.h"
#include "test_worlds.h"

#include <gtest/gtest.h>

#include <optional>

namespace physltl::knowledge {
namespace {

using testing::add_box;
using testing::add_region;
using testing::add_wall;
using testing::open_world;

// The open workspace split by a wall at x = 1 with an optional doorway centred on y = 0; p lies in the
// east room, the robot starts in the west.
scenario::World two_rooms(std::optional<double> doorway_width) {
  auto w = open_world();
  const double half_gap = doorway_width.value_or(0.0) / 2;
  add_wall(w, "divider_south", {0.9, -3.0}, {1.1, -half_gap});
  add_wall(w, "divider_north", {0.9, half_gap}, {1.1, 3.0});
  add_region(w, "p", {2.0, -0.25}, {2.5, 0.25});
  return w;
}

Feasibility feasibility(const scenario::World& w) { return evaluate_feasibility(formulate(w)); }

TEST(Feasibility, RegionThroughADoorwayWiderThanTheRobotIsReachable) {
  EXPECT_TRUE(feasibility(two_rooms(0.8)).invalid.empty());
  EXPECT_TRUE(feasibility(two_rooms(0.56)).invalid.empty());  // 6 cm to spare, a little more than two cells
}

TEST(Feasibility, RegionBehindClosedWallsIsInvalidAsEnclosed) {
  const Feasibility f = feasibility(two_rooms(std::nullopt));
  ASSERT_EQ(f.invalid_names(), std::vector<std::string>{"p"});
  EXPECT_EQ(f.invalid[0].why, Unreachability::kEnclosed);
  EXPECT_EQ(f.invalid[0].reason, "p: region enclosed by fixed walls");
}

TEST(Feasibility, RegionBehindAGapNarrowerThanTheRobotIsInvalidAsTooNarrow) {
  const Feasibility f = feasibility(two_rooms(0.4));  // the robot is 0.5 m wide
  ASSERT_NE(f.find("p"), nullptr);
  EXPECT_EQ(f.find("p")->why, Unreachability::kGapNarrowerThanRobot);
  EXPECT_NE(f.find("p")->reason.find("gap narrower than the robot"), std::string::npos) << f.find("p")->reason;
}

TEST(Feasibility, MovableBoxInTheDoorwayDoesNotBlock) {
  auto w = two_rooms(0.8);
  add_box(w, "B", {1.0, 0.0}, {0.5, 0.7});
  EXPECT_TRUE(feasibility(w).invalid.empty());
}

TEST(Feasibility, UnpushableHeavyBoxClosingTheDoorwayMakesTheRoomInvalid) {
  auto w = two_rooms(0.8);
  add_box(w, "Safe", {1.0, 0.0}, {0.5, 0.8}, /*mass=*/10.0);
  const Feasibility f = feasibility(w);
  ASSERT_NE(f.find("p"), nullptr);
  EXPECT_EQ(f.find("p")->why, Unreachability::kBlockedByUnpushableBodies);
  EXPECT_NE(f.find("p")->reason.find("Safe"), std::string::npos) << f.find("p")->reason;
}

TEST(Feasibility, RegionInsideASlotNarrowerThanTheRobotHasNoRoomForIt) {
  auto w = open_world();
  add_wall(w, "slot_south", {1.5, -0.35}, {3.0, -0.15});
  add_wall(w, "slot_north", {1.5, 0.15}, {3.0, 0.35});
  add_region(w, "p", {2.0, -0.1}, {2.5, 0.1});
  const Feasibility f = feasibility(w);
  ASSERT_NE(f.find("p"), nullptr);
  EXPECT_EQ(f.find("p")->why, Unreachability::kNoRoomForRobot);
}

TEST(Feasibility, RegionSmallerThanAGridCellIsJudgedByItsOwnPoints) {
  auto w = open_world();
  add_region(w, "speck", {0.501, 0.501}, {0.509, 0.509});
  EXPECT_TRUE(feasibility(w).invalid.empty());

  auto closed = two_rooms(std::nullopt);
  add_region(closed, "speck", {2.001, 1.001}, {2.009, 1.009});
  EXPECT_EQ(feasibility(closed).find("speck")->why, Unreachability::kEnclosed);
}

TEST(Feasibility, RegionTheRobotCanOnlyPartlyEnterIsReachable) {
  auto w = open_world();
  add_wall(w, "block", {1.0, -1.0}, {2.0, 1.0});
  add_region(w, "p", {0.5, -0.5}, {1.5, 0.5});  // half of it under the wall
  EXPECT_TRUE(feasibility(w).invalid.empty());
}

TEST(GridCellSize, IsATenthOfTheRobotRadiusKeptBetweenTwoAndFiveCentimetres) {
  auto w = open_world();
  auto cell = [&](double radius) {
    w.robot.radius = radius;
    return grid_cell_size(formulate(w));
  };
  EXPECT_DOUBLE_EQ(cell(0.25), 0.025);
  EXPECT_DOUBLE_EQ(cell(0.1), 0.02);
  EXPECT_DOUBLE_EQ(cell(1.0), 0.05);
  EXPECT_DOUBLE_EQ(cell(0.01), 0.01);  // never above the radius, so grown walls cannot be stepped over
}

TEST(GridCellSize, GrowsInAHugeWorkspaceToKeepTheGridBounded) {
  auto w = open_world(/*half=*/500.0);
  const double cell = grid_cell_size(formulate(w));
  EXPECT_GT(cell, 0.05);
  EXPECT_LE((1000.0 / cell) * (1000.0 / cell), static_cast<double>(kMaxGridCells) * 1.001);
}

}  // namespace
}  // namespace physltl::knowledge
