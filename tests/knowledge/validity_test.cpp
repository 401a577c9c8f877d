// VALIDITYCHECKER rules on hand-made states and contacts, no physics.

#include "physltl/knowledge/validity.h"
#include "test_worlds.h"

#include <gtest/gtest.h>

#include <vector>

namespace physltl::knowledge {
namespace {

using geometry::Vec2;

using scenario::RobotContact;
using testing::add_box;
using testing::add_wall;
using testing::open_world;

// A wall at x = 2, a free box F, a box C in a corridor (pushable along y only) and a box H too heavy to
// push.
class ValidityTest : public ::testing::Test {
 protected:
  ValidityTest() : world_(make_world()), knowledge_(formulate(world_)), state_(scenario::EnvironmentState::initial(world_)) {
    kappa_ = infer(knowledge_, state_);
  }

  static scenario::World make_world() {
    auto w = open_world();
    add_wall(w, "wall", {2.0, -1.0}, {2.2, 1.0});
    add_box(w, "F", {-1.5, 1.5}, {0.5, 0.5});
    add_box(w, "C", {0, 0}, {0.5, 1.0});
    add_wall(w, "corridor_west", {-0.65, -0.5}, {-0.45, 0.5});
    add_wall(w, "corridor_east", {0.45, -0.5}, {0.65, 0.5});
    add_box(w, "H", {1.5, -2.0}, {0.5, 0.5}, /*mass=*/10.0);
    return w;
  }

  Validity check(Vec2 robot, std::vector<RobotContact> contacts, ValidityMode mode = ValidityMode::kKnowledge) {
    state_.robot_position = robot;
    return check_validity(knowledge_, kappa_, state_, contacts, mode);
  }

  static RobotContact touching_movable(int index, Vec2 point) { return {RobotContact::Body::kMovable, index, point}; }

  static constexpr int kFree = 0, kCorridorBox = 1, kHeavy = 2;
  scenario::World world_;
  AbstractKnowledge knowledge_;
  scenario::EnvironmentState state_;
  Kappa kappa_;
};

TEST_F(ValidityTest, TheSetUpHasTheBodyTypesTheTestsAssume) {
  EXPECT_EQ(kappa_.bodies[kFree].type, BodyType::kFree);
  EXPECT_EQ(kappa_.bodies[kCorridorBox].type, BodyType::kConstraintOriented);
  EXPECT_EQ(kappa_.bodies[kHeavy].type, BodyType::kImmovable);
}

TEST_F(ValidityTest, RobotInTheOpenWithoutContactsIsValid) {
  EXPECT_TRUE(check({-2, -2}, {}).valid());
}

TEST_F(ValidityTest, TouchingAFixedBodyIsInvalidWithOrWithoutKnowledge) {
  const std::vector<RobotContact> contacts{{RobotContact::Body::kFixed, 0, {2.0, 0.0}}};
  for (ValidityMode mode : {ValidityMode::kKnowledge, ValidityMode::kBaseline}) {
    const Validity v = check({1.75, 0}, contacts, mode);
    EXPECT_EQ(v.violation, Violation::kTouchesFixedBody);
    EXPECT_EQ(v.body_index, 0);
  }
}

TEST_F(ValidityTest, TouchingAFreeBodyFromAnySideIsValid) {
  EXPECT_TRUE(check({-2.0, 1.5}, {touching_movable(kFree, {-1.75, 1.5})}).valid());
  EXPECT_TRUE(check({-1.5, 1.0}, {touching_movable(kFree, {-1.5, 1.25})}).valid());
}

TEST_F(ValidityTest, PushingAConstraintOrientedBodyFromAnActiveMRegionIsValid) {
  EXPECT_TRUE(check({0.0, -0.75}, {touching_movable(kCorridorBox, {0.0, -0.5})}).valid());
  EXPECT_TRUE(check({0.1, 0.76}, {touching_movable(kCorridorBox, {0.1, 0.5})}).valid());
}

TEST_F(ValidityTest, TouchingAConstraintOrientedBodyFromAForbiddenSideIsInvalid) {
  // Pretend the robot got squeezed against the +x side, whose mRegion the corridor wall occupies.
  const Validity v = check({0.5, 0.0}, {touching_movable(kCorridorBox, {0.25, 0.0})});
  EXPECT_EQ(v.violation, Violation::kPushesFromForbiddenSide);
  EXPECT_EQ(v.body_index, kCorridorBox);
}

TEST_F(ValidityTest, ACentreJustPastTheEndOfAnActiveMRegionStillPushesFromThatSide) {
  // 5 cm beyond the end of the -y side's strip, within kPushSideSlack: the robot brushing the corner
  // while it works the box along a lane.
  EXPECT_TRUE(check({0.30, -0.74}, {touching_movable(kCorridorBox, {0.25, -0.5})}).valid());
}

TEST_F(ValidityTest, TouchingAConstraintOrientedBodyAtACornerIsInvalid) {
  // The centre is diagonally off the corner: in front of neither side, so not in any mRegion.
  EXPECT_EQ(check({0.43, -0.68}, {touching_movable(kCorridorBox, {0.25, -0.5})}).violation,
            Violation::kPushesFromForbiddenSide);
}

TEST_F(ValidityTest, TouchingABodyTooHeavyToPushIsInvalid) {
  EXPECT_EQ(check({1.0, -2.0}, {touching_movable(kHeavy, {1.25, -2.0})}).violation, Violation::kTouchesImmovableBody);
}

TEST_F(ValidityTest, MovableBodyLeavingTheWorkspaceIsInvalid) {
  state_.movable_poses[kFree].position = {-2.9, 1.5};  // pokes 0.15 m out of the west bound
  const Validity v = check({-2, -2}, {});
  EXPECT_EQ(v.violation, Violation::kLeftWorkspace);
  EXPECT_EQ(v.body_index, kFree);
}

TEST_F(ValidityTest, BodyPokingOutByLessThanTheToleranceIsStillInside) {
  state_.movable_poses[kFree].position = {-2.75 - 0.5 * kWorkspaceTolerance, 1.5};
  EXPECT_TRUE(check({-2, -2}, {}).valid());
}

TEST_F(ValidityTest, RobotLeavingTheWorkspaceIsInvalid) {
  EXPECT_EQ(check({0, 2.9}, {}).violation, Violation::kLeftWorkspace);
  EXPECT_EQ(check({0, 2.9}, {}, ValidityMode::kBaseline).violation, Violation::kLeftWorkspace);
}

TEST_F(ValidityTest, BaselineIgnoresMRegionsAndBodyTypes) {
  EXPECT_TRUE(check({0.5, 0.0}, {touching_movable(kCorridorBox, {0.25, 0.0})}, ValidityMode::kBaseline).valid());
  EXPECT_TRUE(check({1.0, -2.0}, {touching_movable(kHeavy, {1.25, -2.0})}, ValidityMode::kBaseline).valid());
}

TEST_F(ValidityTest, BaselineDoesNotNeedKappa) {
  state_.robot_position = {-2, -2};
  EXPECT_TRUE(is_valid(knowledge_, Kappa{}, state_, {}, ValidityMode::kBaseline));
  EXPECT_THROW(is_valid(knowledge_, Kappa{}, state_, {}, ValidityMode::kKnowledge), std::invalid_argument);
}

TEST_F(ValidityTest, IsValidAgreesWithCheckValidity) {
  state_.robot_position = {1.75, 0};
  const std::vector<RobotContact> contacts{{RobotContact::Body::kFixed, 0, {2.0, 0.0}}};
  EXPECT_FALSE(is_valid(knowledge_, kappa_, state_, contacts));
  EXPECT_TRUE(is_valid(knowledge_, kappa_, state_, {}));
}

}  // namespace
}  // namespace physltl::knowledge
