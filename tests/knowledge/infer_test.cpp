// INFERENCE: which mRegions are usable in a state, and the body types that follow.

#include "physltl/knowledge/kappa.h"
#include "test_worlds.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <numbers>
#include <random>
#include <string>

namespace physltl::knowledge {
namespace {

using geometry::Vec2;

using testing::add_box;
using testing::add_wall;
using testing::open_world;
using testing::sides;

Kappa initial_kappa(const scenario::World& w) {
  return infer(formulate(w), scenario::EnvironmentState::initial(w));
}

TEST(Infer, BoxInTheOpenIsFreeWithEveryMRegionActive) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 0.5});
  const Kappa kappa = initial_kappa(w);
  ASSERT_EQ(kappa.bodies.size(), 1u);
  EXPECT_EQ(kappa.bodies[0].type, BodyType::kFree);
  EXPECT_EQ(sides(kappa.bodies[0].active_faces), "-x +x -y +y");
}

TEST(Infer, WallsCloserThanTheRobotsDiameterDeactivateTheSidesFacingThem) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 1.0});
  add_wall(w, "west", {-0.65, -1.5}, {-0.45, 1.5});  // 0.2 m gap: the robot (0.5 m) cannot stand there
  add_wall(w, "east", {0.45, -1.5}, {0.65, 1.5});
  const Kappa kappa = initial_kappa(w);
  EXPECT_EQ(kappa.bodies[0].type, BodyType::kConstraintOriented);
  EXPECT_EQ(sides(kappa.bodies[0].active_faces), "-y +y");
}

TEST(Infer, WallFartherThanTheRobotsDiameterLeavesTheSideActive) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 0.5});
  add_wall(w, "east", {0.76, -1.0}, {0.96, 1.0});  // 0.51 m gap
  EXPECT_EQ(initial_kappa(w).bodies[0].type, BodyType::kFree);
}

TEST(Infer, SideStaysActiveWhileTheRobotFitsAlongPartOfIt) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 2.0});
  // The wall faces only the upper half of the +x side; the robot can still push at the lower end.
  add_wall(w, "east", {0.35, 0.2}, {0.55, 1.5});
  EXPECT_TRUE(initial_kappa(w).bodies[0].active_faces.contains(testing::face(Side::kPlusX)));
  w.fixed_bodies[0].footprint.shape = geometry::Shape::box({w.fixed_bodies[0].footprint.shape.half_extents().x(), 1.2});  // now it faces the whole side
  w.fixed_bodies[0].footprint.pose.position.y() = 0.0;
  EXPECT_FALSE(initial_kappa(w).bodies[0].active_faces.contains(testing::face(Side::kPlusX)));
}

TEST(Infer, AnotherBoxBlocksTheSideItSitsAgainstAndTheTypeIsRestoredWhenItLeaves) {
  auto w = open_world();
  add_box(w, "A", {0, 0}, {0.5, 0.5});
  add_box(w, "B", {0, 2}, {0.5, 0.5});
  const auto k = formulate(w);
  auto state = scenario::EnvironmentState::initial(w);
  EXPECT_EQ(infer(k, state).bodies[0].type, BodyType::kFree);

  state.movable_poses[1].position = {0.1, 0.6};  // B's lower side 0.1 m above A's upper side
  const Kappa blocked = infer(k, state);
  EXPECT_EQ(sides(blocked.bodies[0].active_faces), "-x +x -y");
  EXPECT_EQ(sides(blocked.bodies[1].active_faces), "-x +x +y");
  EXPECT_EQ(blocked.bodies[0].type, BodyType::kConstraintOriented);

  state.movable_poses[1].position = {0, 2};
  EXPECT_EQ(infer(k, state).bodies[0].type, BodyType::kFree);
}

TEST(Infer, WorkspaceBoundaryBlocksTheSideFacingItEvenWithoutWalls) {
  auto w = open_world(/*half=*/3.0);
  add_box(w, "B", {2.6, 0}, {0.5, 0.5});  // 0.15 m from the east bound
  EXPECT_EQ(sides(initial_kappa(w).bodies[0].active_faces), "-x -y +y");
}

TEST(Infer, BoxBlockedOnEverySideIsImmovable) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 0.5});
  add_wall(w, "west", {-0.55, -0.55}, {-0.35, 0.55});
  add_wall(w, "east", {0.35, -0.55}, {0.55, 0.55});
  add_wall(w, "south", {-0.35, -0.55}, {0.35, -0.35});
  add_wall(w, "north", {-0.35, 0.35}, {0.35, 0.55});
  const Kappa kappa = initial_kappa(w);
  EXPECT_EQ(kappa.bodies[0].type, BodyType::kImmovable);
  EXPECT_TRUE(kappa.bodies[0].active_faces.empty());
}

TEST(Infer, BodyTooHeavyToPushIsImmovableEvenInTheOpen) {
  auto w = open_world();
  add_box(w, "Safe", {0, 0}, {0.5, 0.5}, /*mass=*/10.0);
  EXPECT_EQ(initial_kappa(w).bodies[0].type, BodyType::kImmovable);
}

TEST(Infer, HeavyBodyStillBlocksTheSidesOfItsNeighbours) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 0.5});
  add_box(w, "Safe", {0.6, 0}, {0.5, 0.5}, /*mass=*/10.0);
  EXPECT_EQ(sides(initial_kappa(w).bodies[0].active_faces), "-x -y +y");
}

TEST(Infer, AuthoredConstraintOrientedBodyNeverBecomesFree) {
  auto w = open_world();
  add_box(w, "Car", {0, 0}, {1.0, 0.5}).push_from = {testing::face(Side::kMinusX), testing::face(Side::kPlusX)};
  const Kappa kappa = initial_kappa(w);
  EXPECT_EQ(kappa.bodies[0].type, BodyType::kConstraintOriented);
  EXPECT_EQ(sides(kappa.bodies[0].active_faces), "-x +x");
}

TEST(Infer, SidesFollowTheBodysRotation) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 1.0});
  add_wall(w, "south", {-1.5, -0.65}, {1.5, -0.45});  // a corridor along world x
  add_wall(w, "north", {-1.5, 0.45}, {1.5, 0.65});
  const auto k = formulate(w);
  auto state = scenario::EnvironmentState::initial(w);
  state.movable_poses[0].yaw = std::numbers::pi / 2;  // the long body axis now lies along world x
  const Kappa kappa = infer(k, state);
  // The body's ±x sides face the walls (world ±y) and are blocked; its ±y sides face along the corridor.
  EXPECT_EQ(sides(kappa.bodies[0].active_faces), "-y +y");
  const auto& south = *std::find_if(k.movable_bodies[0].mregions.begin(), k.movable_bodies[0].mregions.end(),
                                     [](const MRegionTemplate& m) { return m.face == testing::face(Side::kMinusY); });
  EXPECT_TRUE(push_direction(south, state.movable_poses[0]).isApprox(Vec2(-1, 0)));
}

TEST(Infer, InPlaceInferenceEqualsFreshInferenceWhateverThePreviousKappa) {
  auto w = open_world();
  add_box(w, "A", {0, 0}, {0.5, 0.5});
  add_box(w, "B", {0.1, 0.6}, {0.5, 0.5});
  const auto k = formulate(w);
  const auto state = scenario::EnvironmentState::initial(w);
  Kappa previous{{{BodyType::kImmovable, {}}, {BodyType::kFree, FaceSet::first(4)}}};
  infer(k, state, previous);
  EXPECT_EQ(previous, infer(k, state));
  EXPECT_EQ(infer(k, state), infer(k, state));
}

// The planner re-infers after every physics step from the previous kappa; bodies moving in and out of
// each other's mRegions must give exactly what a fresh inference gives.
TEST(Reinfer, EqualsFreshInferenceAlongRandomMovesInACrowdedRoom) {
  auto w = open_world(2.5);
  add_wall(w, "middle", {-0.1, -2.5}, {0.1, 0.5});
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) {
      add_box(w, "B" + std::to_string(row * 4 + column), {-1.8 + 1.2 * column, -1.5 + 1.2 * row}, {0.5, 0.4});
    }
  }
  const auto k = formulate(w);
  auto state = scenario::EnvironmentState::initial(w);
  Kappa kappa = infer(k, state);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> step(-0.15, 0.15), anywhere(-2.2, 2.2);
  int changes = 0;
  BodyLocator inferred_for(k, state.movable_poses);
  for (int i = 0; i < 3000; ++i) {
    const Kappa kappa_before = kappa;
    for (int moves = 1 + static_cast<int>(random() % 3); moves > 0; --moves) {
      auto& pose = state.movable_poses[random() % state.movable_poses.size()];
      if (random() % 20 == 0) {
        pose.position = {anywhere(random), anywhere(random)};  // a jump across the room
      } else {
        pose.position += Vec2(step(random), step(random));
        pose.yaw += 0.3 * step(random);
      }
    }
    reinfer(k, state, inferred_for, kappa);
    // Against every body scanned: one grid cell as large as the workspace.
    Kappa scanned;
    infer(k, state, BodyLocator(k, state.movable_poses, k.workspace.size().maxCoeff()), scanned);
    ASSERT_EQ(kappa, scanned) << "move " << i;
    ASSERT_TRUE(std::equal(inferred_for.poses().begin(), inferred_for.poses().end(), state.movable_poses.begin(),
                           [](const auto& a, const auto& b) { return a.position == b.position && a.yaw == b.yaw; }));
    changes += kappa != kappa_before;
  }
  EXPECT_GT(changes, 300);  // the moves did block and free mRegions
}

TEST(Reinfer, WithNothingMovedKeepsKappa) {
  auto w = open_world();
  add_box(w, "A", {0, 0}, {0.5, 0.5});
  const auto k = formulate(w);
  const auto state = scenario::EnvironmentState::initial(w);
  Kappa kappa{{{BodyType::kImmovable, {}}}};  // deliberately not this state's: nothing moved, nothing redone
  BodyLocator inferred_for(k, state.movable_poses);
  reinfer(k, state, inferred_for, kappa);
  EXPECT_EQ(kappa.bodies[0].type, BodyType::kImmovable);
}

TEST(Infer, RejectsAStateWithADifferentNumberOfBodies) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 0.5});
  scenario::EnvironmentState state;
  EXPECT_THROW(infer(formulate(w), state), std::invalid_argument);
}

TEST(MRegionAt, PlacesTheStripInTheWorldFrame) {
  auto w = open_world();
  add_box(w, "B", {1, 2}, {0.5, 1.0});
  const auto knowledge = formulate(w);
  const auto& body = knowledge.movable_bodies[0];
  const geometry::Pose2 pose{{1, 2}, std::numbers::pi / 2};
  const auto strip = mregion_at(body.mregions[1], pose);  // +x side, now facing world +y
  ASSERT_EQ(body.mregions[1].face, testing::face(Side::kPlusX));
  EXPECT_TRUE(strip.pose.position.isApprox(Vec2(1, 2 + 0.25 + 0.275)));
  EXPECT_TRUE(strip.contains({1, 2.5}));
  EXPECT_FALSE(strip.contains({1, 1.5}));
}

}  // namespace
}  // namespace physltl::knowledge
