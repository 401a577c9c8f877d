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

// BODY@REGION for the world's first movable body and its region named `region`.
Feasibility object_feasibility(const scenario::World& w, const std::string& body, const std::string& region) {
  const AbstractKnowledge k = formulate(w);
  int b = 0, r = 0;
  while (k.movable_bodies[static_cast<size_t>(b)].name != body) ++b;
  while (k.propositions[static_cast<size_t>(r)].name != region) ++r;
  const ObjectProposition object{body + "@" + region, {b}, {r}};
  return evaluate_feasibility(k, std::span(&object, 1));
}

TEST(ObjectFeasibility, ABodyTooHeavyToPushIsAlwaysWhereItStandsAndNeverElsewhere) {
  auto w = open_world();
  add_box(w, "Safe", {0.0, 0.0}, {0.6, 0.6}, /*mass=*/12.0);  // 0.5 * 12 * 9.81 = 58.9 N > 20 N
  add_region(w, "vault", {-0.5, -0.5}, {0.5, 0.5});
  add_region(w, "dock", {1.5, 1.5}, {2.5, 2.5});
  const Feasibility stays = object_feasibility(w, "Safe", "vault");
  ASSERT_EQ(stays.objects.size(), 1u);
  EXPECT_TRUE(stays.objects[0].always_true);
  EXPECT_EQ(stays.always_true_names(), std::vector<std::string>{"Safe@vault"});
  EXPECT_EQ(stays.find("Safe@vault"), nullptr);
  const Feasibility never = object_feasibility(w, "Safe", "dock");
  ASSERT_NE(never.find("Safe@dock"), nullptr);
  EXPECT_EQ(never.find("Safe@dock")->why, Unreachability::kBodyCannotMove);
  EXPECT_EQ(never.find("Safe@dock")->reason,
            "Safe@dock: Safe is too heavy to push: its floor friction holds it with 58.9 N, the robot's drive pushes "
            "with at most 20.0 N");
}

// A bay closed on three sides whose opening is narrower than the box: its centre never gets in, whatever
// the robot does; a box narrow enough does.
TEST(ObjectFeasibility, ABayWhoseOpeningIsNarrowerThanTheBodyIsRefusedWithItsReason) {
  auto w = open_world();
  add_wall(w, "bay_west", {1.0, 1.0}, {1.2, 2.9});
  add_wall(w, "bay_east", {1.7, 1.0}, {1.9, 2.9});
  add_wall(w, "bay_back", {1.0, 2.9}, {1.9, 3.0});
  add_region(w, "bay", {1.2, 2.0}, {1.7, 2.8});  // the opening is 0.5 m wide
  add_box(w, "Wide", {-1.0, 0.0}, {0.6, 0.6});
  add_box(w, "Narrow", {0.5, -1.0}, {0.4, 0.4});
  const Feasibility wide = object_feasibility(w, "Wide", "bay");
  ASSERT_NE(wide.find("Wide@bay"), nullptr);
  EXPECT_EQ(wide.find("Wide@bay")->why, Unreachability::kBodyCannotGetThere);
  EXPECT_EQ(wide.find("Wide@bay")->reason,
            "Wide@bay: no way for the centre of Wide into bay: every way in is narrower than Wide (0.60 m across) "
            "among the fixed bodies");
  EXPECT_EQ(object_feasibility(w, "Narrow", "bay").find("Narrow@bay"), nullptr);  // 0.4 m wide
}

// A U whose centroid lies in its notch, round a post standing there: its centre starts on the post, where
// no disc fits, yet the U moves freely. A centre outside its body says nothing of where the body fits.
TEST(ObjectFeasibility, ABodyWhoseCentreLiesOutsideItIsNotJudgedByItsCentre) {
  auto w = open_world();
  const scenario::MovableBody& u = testing::add_polygon(
      w, "U", {{-0.6, -0.5}, {0.6, -0.5}, {0.6, 0.6}, {0.3, 0.6}, {0.3, -0.3}, {-0.3, -0.3}, {-0.3, 0.6}, {-0.6, 0.6}});
  ASSERT_FALSE(geometry::contains(u.footprint.shape, u.footprint.pose, u.footprint.pose.position)) << "the centroid is in the notch";
  EXPECT_EQ(u.footprint.shape.centre_clearance(), 0.0);
  scenario::FixedBody post;
  post.name = "post";
  post.footprint = {u.footprint.pose, geometry::Shape::circle(0.15)};
  w.fixed_bodies.push_back(post);
  add_region(w, "dock", {1.5, 1.5}, {2.5, 2.5});
  EXPECT_EQ(object_feasibility(w, "U", "dock").find("U@dock"), nullptr);
}

// A group's proposition holds only when each of its bodies is in one of its regions: one body that can
// get into none makes it unreachable, named in the reason; a region it can get into makes it reachable.
TEST(ObjectFeasibility, AGroupIsUnreachableWhenOneOfItsBodiesCanGetIntoNoneOfItsRegions) {
  auto w = open_world();
  add_wall(w, "bay_west", {1.0, 1.0}, {1.2, 2.9});
  add_wall(w, "bay_east", {1.7, 1.0}, {1.9, 2.9});
  add_wall(w, "bay_back", {1.0, 2.9}, {1.9, 3.0});
  add_region(w, "bay", {1.2, 2.0}, {1.7, 2.8});  // the opening is 0.5 m wide
  add_region(w, "dock", {-2.5, -2.5}, {-1.5, -1.5});
  add_box(w, "Narrow", {0.5, -1.0}, {0.4, 0.4});
  add_box(w, "Wide", {-1.0, 0.0}, {0.6, 0.6});
  const AbstractKnowledge k = formulate(w);
  const std::vector<ObjectProposition> groups{{"boxes@bays", {0, 1}, {0}}, {"boxes@places", {0, 1}, {0, 1}}};
  const Feasibility f = evaluate_feasibility(k, groups);
  ASSERT_NE(f.find("boxes@bays"), nullptr);
  EXPECT_EQ(f.find("boxes@bays")->why, Unreachability::kBodyCannotGetThere);
  EXPECT_EQ(f.find("boxes@bays")->reason,
            "boxes@bays: no way for the centre of Wide into bays: every way in is narrower than Wide (0.60 m across) "
            "among the fixed bodies");
  EXPECT_EQ(f.find("boxes@places"), nullptr);  // Wide into the dock, Narrow into either
}

TEST(ObjectFeasibility, ARegionPartlyInsideAWallStillCountsWhereTheCentreFits) {
  auto w = open_world();
  add_wall(w, "wall", {1.0, -3.0}, {1.2, 3.0});
  add_region(w, "strip", {0.4, -0.5}, {1.1, 0.5});  // overlaps the wall; the box's centre fits at x <= 0.7
  add_box(w, "B", {-1.0, 0.0}, {0.6, 0.6});
  EXPECT_EQ(object_feasibility(w, "B", "strip").find("B@strip"), nullptr);
}

}  // namespace
}  // namespace physltl::knowledge
