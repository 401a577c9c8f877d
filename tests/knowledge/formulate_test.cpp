// OntologyFormulation: body classes, robot capabilities and mRegion templates from a World.

#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/kappa.h"
#include "test_worlds.h"

#include <gtest/gtest.h>

#include <set>

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

// A U of outline width 1.6 m and depth 1 m, its notch `notch` wide and 0.6 m deep, open towards +y:
// faces 3, 4 and 5 (counted from 0; push_from says 4 to 6) are its right side, bottom and left side.
scenario::MovableBody& add_u(scenario::World& w, double notch) {
  const double h = notch / 2;
  return testing::add_polygon(w, "U", {{-0.8, -0.5}, {0.8, -0.5}, {0.8, 0.5}, {h, 0.5}, {h, -0.1}, {-h, -0.1}, {-h, 0.5}, {-0.8, 0.5}});
}

std::set<int> faces_of(const MovableBodyKnowledge& body) {
  std::set<int> faces;
  for (const MRegionTemplate& m : body.mregions) faces.insert(m.face);
  return faces;
}

TEST(Formulate, NoMRegionInsideANotchNarrowerThanTheRobotButOnEveryFaceOfAWideOne) {
  auto narrow = open_world();  // the robot: 0.25 m radius
  add_u(narrow, 0.4);
  const auto k = formulate(narrow);
  const MovableBodyKnowledge& u = k.movable_bodies[0];
  EXPECT_EQ(faces_of(u), (std::set<int>{0, 1, 2, 6, 7})) << "the notch's sides and bottom are out of the robot's reach";
  EXPECT_EQ(u.body_class, BodyClass::kFreelyMovable);
  EXPECT_NE(u.class_reason.find("the robot can touch"), std::string::npos) << u.class_reason;
  // Open space all round: every face it has is active, so it is free (the notch does not count against it).
  EXPECT_EQ(infer(k, scenario::EnvironmentState::initial(narrow)).bodies[0].type, BodyType::kFree);

  auto wide = open_world();
  add_u(wide, 0.8);
  EXPECT_EQ(faces_of(formulate(wide).movable_bodies[0]).size(), 8u) << "a notch the robot fits in is pushed from inside";
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
