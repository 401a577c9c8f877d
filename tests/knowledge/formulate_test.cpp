// OntologyFormulation: body classes, robot capabilities and mRegion templates from a World.

#include "physltl/knowledge/abstract_knowledge.h"
#include "test_worlds.h"

#include <gtest/gtest.h>

namespace physltl::knowledge {
namespace {

using geometry::Vec2;

using testing::add_box;
using testing::add_wall;
using testing::open_world;

const MRegionTemplate& mregion(const MovableBodyKnowledge& body, Side side) {
  for (const auto& m : body.mregions) {
    if (m.face == testing::face(side)) return m;
  }
  throw std::runtime_error("no mRegion on that side");
}

TEST(Formulate, MovableBodyWithoutAuthoredSidesIsFreelyMovableWithAnMRegionOnEachSide) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 0.5});
  const auto k = formulate(w);
  ASSERT_EQ(k.movable_bodies.size(), 1u);
  EXPECT_EQ(k.movable_bodies[0].body_class, BodyClass::kFreelyMovable);
  EXPECT_EQ(k.movable_bodies[0].mregions.size(), 4u);
}

TEST(Formulate, AuthoredPushSidesMakeABodyConstraintOrientedWithOnlyThoseMRegions) {
  auto w = open_world();
  add_box(w, "Car", {0, 0}, {1.0, 0.5}).push_from = {testing::face(Side::kPlusX), testing::face(Side::kMinusX)};
  const auto k = formulate(w);
  const auto& car = k.movable_bodies[0];
  EXPECT_EQ(car.body_class, BodyClass::kConstraintOriented);
  ASSERT_EQ(car.mregions.size(), 2u);
  EXPECT_EQ(car.mregions[0].face, testing::face(Side::kMinusX));
  EXPECT_EQ(car.mregions[1].face, testing::face(Side::kPlusX));
  EXPECT_NE(car.class_reason.find("-x"), std::string::npos) << car.class_reason;
}

TEST(Formulate, AuthoringAllFourSidesIsTheSameAsAuthoringNone) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 0.5}).push_from = {testing::face(Side::kPlusY), testing::face(Side::kMinusX), testing::face(Side::kMinusY), testing::face(Side::kPlusX)};
  EXPECT_EQ(formulate(w).movable_bodies[0].body_class, BodyClass::kFreelyMovable);
}

TEST(Formulate, DefaultMRegionIsAsWideAsTheSideAndAsDeepAsTheRobotDiameterPlusAMargin) {
  auto w = open_world();
  add_box(w, "B", {1, 1}, {0.5, 1.0});
  const auto knowledge = formulate(w);
  const auto& body = knowledge.movable_bodies[0];
  const double depth = 2 * 0.25 + FormulationSettings{}.mregion_margin;

  const MRegionTemplate& east = mregion(body, Side::kPlusX);
  EXPECT_NEAR(east.strip.pose.position.x(), 0.25 + depth / 2, 1e-12);
  EXPECT_NEAR(east.strip.pose.position.y(), 0.0, 1e-12);
  EXPECT_NEAR(east.strip.half_extents.x(), depth / 2, 1e-12);
  EXPECT_NEAR(east.strip.half_extents.y(), 0.5, 1e-12);  // the side is 1.0 m long

  const MRegionTemplate& south = mregion(body, Side::kMinusY);
  EXPECT_NEAR(south.strip.pose.position.y(), -(0.5 + depth / 2), 1e-12);
  EXPECT_NEAR(south.strip.half_extents.x(), 0.25, 1e-12);
  // The robot touching the south side has its centre one radius below it, anywhere along the side.
  EXPECT_TRUE(south.contact_from.isApprox(Vec2(-0.25, -0.75)));
  EXPECT_TRUE(south.contact_to.isApprox(Vec2(0.25, -0.75)));
}

TEST(Formulate, AuthoredMRegionDepthOverridesTheDefault) {
  auto w = open_world();
  add_box(w, "B", {0, 0}, {0.5, 0.5}).mregion_depth = 0.8;
  EXPECT_NEAR(mregion(formulate(w).movable_bodies[0], Side::kPlusY).strip.half_extents.y(), 0.4, 1e-12);
}

// The robot rolls on its wheels: its drive's whole force bound is there to push with, as the physics
// applies it (physics::Simulation).
TEST(Formulate, PushForceIsTheDrivesWholeForceBound) {
  auto w = open_world();
  w.robot.max_force = 12.5;
  EXPECT_EQ(formulate(w).robot.push_force, 12.5);
}

TEST(Formulate, BodyTooHeavyForTheRobotIsTreatedAsFixedWithTheForcesInTheReason) {
  auto w = open_world();
  add_box(w, "Safe", {0, 0}, {0.5, 0.5}, /*mass=*/10.0);  // 0.5 * 10 * 9.81 = 49.05 N > 20 N
  const auto knowledge = formulate(w);
  const auto& safe = knowledge.movable_bodies[0];
  EXPECT_EQ(safe.body_class, BodyClass::kFixed);
  EXPECT_TRUE(safe.mregions.empty());
  EXPECT_NE(safe.class_reason.find("too heavy"), std::string::npos) << safe.class_reason;
  EXPECT_NE(safe.class_reason.find("49.1 N"), std::string::npos) << safe.class_reason;
}

TEST(Formulate, FloorFrictionCombinesTheBodysAndTheFloorsCoefficients) {
  auto w = open_world();
  auto& b = add_box(w, "B", {0, 0}, {0.5, 0.5}, /*mass=*/3.8);  // 0.5 * 3.8 * 9.81 = 18.6 N < 20 N
  b.friction = 0.5;
  EXPECT_EQ(formulate(w).movable_bodies[0].body_class, BodyClass::kFreelyMovable);
  w.workspace.floor_friction = 0.6;  // sqrt(0.5 * 0.6) * 3.8 * 9.81 = 20.4 N
  const auto k = formulate(w);
  EXPECT_NEAR(k.movable_bodies[0].floor_friction_force, std::sqrt(0.3) * 3.8 * 9.81, 1e-9);
  EXPECT_EQ(k.movable_bodies[0].body_class, BodyClass::kFixed);
}

TEST(Formulate, KeepsFixedBodiesAndPropositionsInWorldOrder) {
  auto w = open_world();
  add_wall(w, "north", {-3, 2.8}, {3, 3});
  add_wall(w, "south", {-3, -3}, {3, -2.8});
  testing::add_region(w, "p1", {0, 0}, {1, 1});
  testing::add_region(w, "p2", {1, 1}, {2, 2});
  const auto k = formulate(w);
  ASSERT_EQ(k.fixed_bodies.size(), 2u);
  EXPECT_EQ(k.fixed_bodies[1].name, "south");
  ASSERT_EQ(k.propositions.size(), 2u);
  EXPECT_EQ(k.propositions[0].name, "p1");
}

}  // namespace
}  // namespace physltl::knowledge
