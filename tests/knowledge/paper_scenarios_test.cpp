// The paper's two worlds (scenarios/rooms.lua and scenarios/ordered.lua) reasoned about as the paper's
// Results section describes.

#include "physltl/knowledge/feasibility.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/knowledge/report.h"
#include "test_worlds.h"

#include <gtest/gtest.h>

namespace physltl::knowledge {
namespace {

using geometry::Vec2;

using testing::movable_index;
using testing::shipped_scenario;
using testing::sides;

std::string push_directions(const BodyKappa& kappa, const MovableBodyKnowledge& body, const geometry::Pose2& pose) {
  std::string out;
  for (const Vec2& d : allowed_push_directions(body, kappa, pose)) out += (out.empty() ? "" : " ") + direction_name(d);
  return out;
}

class Rooms : public ::testing::Test {
 protected:
  Rooms()
      : world_(shipped_scenario("rooms.lua")),
        knowledge_(formulate(world_)),
        state_(scenario::EnvironmentState::initial(world_)),
        kappa_(infer(knowledge_, state_)) {}

  const BodyKappa& body(const std::string& name) const { return kappa_.bodies[movable_index(world_, name)]; }

  scenario::World world_;
  AbstractKnowledge knowledge_;
  scenario::EnvironmentState state_;
  Kappa kappa_;
};

TEST_F(Rooms, OnlyP3IsInvalidBecauseRoom3IsEnclosed) {
  const Feasibility f = evaluate_feasibility(knowledge_);
  ASSERT_EQ(f.invalid_names(), std::vector<std::string>{"p3"});
  EXPECT_EQ(f.invalid[0].reason, "p3: region enclosed by fixed walls");
}

TEST_F(Rooms, EveryBoxIsFreelyMovableInK) {
  for (const auto& b : knowledge_.movable_bodies) EXPECT_EQ(b.body_class, BodyClass::kFreelyMovable) << b.name;
}

TEST_F(Rooms, B1InItsCorridorIsConstraintOrientedAndPushableOnlyAlongTheCorridor) {
  const size_t b1 = movable_index(world_, "B1");
  EXPECT_EQ(kappa_.bodies[b1].type, BodyType::kConstraintOriented);
  EXPECT_EQ(sides(kappa_.bodies[b1].active_faces), "-y +y");
  EXPECT_EQ(push_directions(kappa_.bodies[b1], knowledge_.movable_bodies[b1], state_.movable_poses[b1]), "+y -y");
}

TEST_F(Rooms, DoorwayBoxesLoseTheSidesFacingTheDoorJambs) {
  for (const char* name : {"B2", "B4"}) {
    EXPECT_EQ(body(name).type, BodyType::kConstraintOriented) << name;
    EXPECT_EQ(sides(body(name).active_faces), "-y +y") << name;
  }
}

TEST_F(Rooms, B1PushedIntoRoom1IsFreeAgain) {
  const size_t b1 = movable_index(world_, "B1");
  state_.movable_poses[b1].position = {-3.0, 3.0};
  EXPECT_EQ(infer(knowledge_, state_).bodies[b1].type, BodyType::kFree);
}

TEST_F(Rooms, B1HalfWayOutOfTheCorridorCanBePushedSidewaysAgain) {
  const size_t b1 = movable_index(world_, "B1");
  state_.movable_poses[b1].position = {-3.0, 2.6};  // its upper 0.7 m are past the corridor walls
  EXPECT_EQ(infer(knowledge_, state_).bodies[b1].type, BodyType::kFree);
}

class Ordered : public ::testing::Test {
 protected:
  Ordered() : world_(shipped_scenario("ordered.lua")), b1_(movable_index(world_, "B1")), b2_(movable_index(world_, "B2")) {}

  Kappa with_b1_at(const Vec2& position) const {
    auto state = scenario::EnvironmentState::initial(world_);
    state.movable_poses[b1_].position = position;
    return infer(formulate(world_), state);
  }

  scenario::World world_;
  size_t b1_;
  size_t b2_;
};

// ordered.lua authors the paper's two-sided boxes: B1 pushed along +x or -y (from its -x or +y side), B2
// along +y or -x (from its -y or +x side).
TEST_F(Ordered, BothBoxesStartWithEveryAuthoredSideActive) {
  const auto k = formulate(world_);
  const auto state = scenario::EnvironmentState::initial(world_);
  const Kappa kappa = infer(k, state);
  EXPECT_EQ(push_directions(kappa.bodies[b1_], k.movable_bodies[b1_], state.movable_poses[b1_]), "+x -y");
  EXPECT_EQ(push_directions(kappa.bodies[b2_], k.movable_bodies[b2_], state.movable_poses[b2_]), "-x +y");
}

TEST_F(Ordered, B1PushedAlongXLeavesB2PushableOnlyAlongMinusX) {
  const auto k = formulate(world_);
  auto state = scenario::EnvironmentState::initial(world_);
  state.movable_poses[b1_].position = {0.9, 0.0};  // just below B2 at (1.0, 0.75), a 0.25 m gap between them
  const Kappa kappa = infer(k, state);
  EXPECT_EQ(kappa.bodies[b2_].type, BodyType::kConstraintOriented);
  EXPECT_EQ(sides(kappa.bodies[b2_].active_faces), "+x");
  EXPECT_EQ(push_directions(kappa.bodies[b2_], k.movable_bodies[b2_], state.movable_poses[b2_]), "-x");
}

TEST_F(Ordered, MovingB1AwayRestoresB2sSides) {
  EXPECT_EQ(sides(with_b1_at({0.9, 0.0}).bodies[b2_].active_faces), "+x");
  EXPECT_EQ(sides(with_b1_at({0.9, -1.0}).bodies[b2_].active_faces), "+x -y");
}

TEST_F(Ordered, EveryRegionIsReachable) {
  EXPECT_TRUE(evaluate_feasibility(formulate(world_)).invalid.empty());
}

}  // namespace
}  // namespace physltl::knowledge
