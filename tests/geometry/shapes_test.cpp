#include "physltl/geometry/shapes.h"

#include <gtest/gtest.h>

#include <numbers>

namespace physltl::geometry {
namespace {

OrientedBox box(double x, double y, double sx, double sy, double yaw = 0.0) {
  return {{{x, y}, yaw}, {sx / 2, sy / 2}};
}

TEST(OrientedBox, BoxesSharingAnEdgeDoNotOverlap) {
  EXPECT_FALSE(overlap(box(0, 0, 1, 1), box(1, 0, 1, 1)));
  EXPECT_TRUE(overlap(box(0, 0, 1, 1), box(0.99, 0, 1, 1)));
}

TEST(OrientedBox, RotatedBoxesOverlapOnlyWhenTheyReallyDo) {
  // A diamond whose corner reaches into the square's side.
  EXPECT_TRUE(overlap(box(0, 0, 1, 1), box(1.1, 0, 1, 1, std::numbers::pi / 4)));
  EXPECT_FALSE(overlap(box(0, 0, 1, 1), box(1.3, 0, 1, 1, std::numbers::pi / 4)));
}

TEST(OrientedBox, DistanceIsZeroInsideAndEuclideanOutside) {
  const OrientedBox b = box(0, 0, 2, 2);
  EXPECT_EQ(b.distance_to({0.5, 0.5}), 0.0);
  EXPECT_NEAR(b.distance_to({4, 5}), 5.0, 1e-12);
}

TEST(OrientedBox, DiscOverlapAccountsForTheRadius) {
  EXPECT_TRUE(overlap(box(0, 0, 2, 2), Vec2(1.2, 0), 0.25));
  EXPECT_FALSE(overlap(box(0, 0, 2, 2), Vec2(1.3, 0), 0.25));
}

TEST(Polygon, ContainsInteriorAndBoundaryButNotOutside) {
  const Polygon l{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};  // an L shape
  EXPECT_TRUE(l.contains({0.5, 1.5}));
  EXPECT_TRUE(l.contains({2, 0.5}));
  EXPECT_FALSE(l.contains({1.5, 1.5}));
}

TEST(Polygon, BowTieIsNotSimple) {
  EXPECT_FALSE((Polygon{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}}).is_simple());
  EXPECT_TRUE(Polygon::from_rect({{0, 0}, {1, 1}}).is_simple());
}

TEST(Polygon, OverlapDetectsCrossingContainmentAndIdentity) {
  const Polygon a = Polygon::from_rect({{0, 0}, {2, 2}});
  EXPECT_TRUE(overlap(a, Polygon::from_rect({{1, 1}, {3, 3}})));          // crossing edges
  EXPECT_TRUE(overlap(a, Polygon::from_rect({{0.5, 0.5}, {1, 1}})));      // inside
  EXPECT_TRUE(overlap(a, a));                                             // identical
  EXPECT_FALSE(overlap(a, Polygon::from_rect({{2, 0}, {3, 2}})));         // shared edge
  EXPECT_FALSE(overlap(a, Polygon::from_rect({{2.5, 2.5}, {3, 3}})));     // apart
}

TEST(Polygon, CentroidOfARectangleIsItsCentre) {
  const Vec2 c = Polygon::from_rect({{1, 2}, {3, 6}}).centroid();
  EXPECT_NEAR(c.x(), 2.0, 1e-12);
  EXPECT_NEAR(c.y(), 4.0, 1e-12);
}

TEST(OrientedBox, InsideARectangleTurnsWithTheBox) {
  const Rect room{{0, 0}, {4, 2}};
  EXPECT_TRUE(inside(box(2, 1, 1, 1), room));
  EXPECT_TRUE(inside(box(0.5, 0.5, 1, 1), room));      // touching two walls
  EXPECT_FALSE(inside(box(0.49, 0.5, 1, 1), room));
  // A 2.2 by 0.2 plank fits lying along the room; turned a quarter it pokes out at the top and bottom.
  EXPECT_TRUE(inside(box(2, 1, 2.2, 0.2), room));
  EXPECT_FALSE(inside(box(2, 1, 2.2, 0.2, std::numbers::pi / 2), room));
  EXPECT_TRUE(inside(box(2, 1, 2.2, 0.2, std::numbers::pi), room));
  // Turned by 45 degrees a unit square reaches sqrt(1/2) from its centre.
  EXPECT_TRUE(inside(box(0.71, 1, 1, 1, std::numbers::pi / 4), room));
  EXPECT_FALSE(inside(box(0.70, 1, 1, 1, std::numbers::pi / 4), room));
  EXPECT_TRUE(inside(box(0.70, 1, 1, 1, std::numbers::pi / 4), room, 0.01));  // within the tolerance
}

}  // namespace
}  // namespace physltl::geometry
