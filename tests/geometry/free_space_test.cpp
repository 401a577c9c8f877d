#include "physltl/geometry/free_space.h"

#include <gtest/gtest.h>

#include <cmath>

namespace physltl::geometry {
namespace {

const Rect kFloor{{-10, -10}, {10, 10}};

Polygon point(double x, double y) { return Polygon{{Vec2(x, y)}}; }

TEST(FreeSpace, AGrownBoxHasEveryCornerOnTheTrueRoundedBoundary) {
  const OrientedBox box{{{1, 2}, 0.4}, {0.5, 0.2}};
  const Polygon grown = grown_from_inside(box, 0.3);
  ASSERT_EQ(grown.vertices.size(), 12u);
  EXPECT_GT(grown.signed_area(), 0.0);  // counter-clockwise
  for (const Vec2& v : grown.vertices) EXPECT_NEAR(box.distance_to(v), 0.3, 1e-12);
  // Chords lie inside the arcs: the polygon is smaller than the box grown by the disc.
  const double rounded_area = 4 * 0.5 * 0.2 + 2 * (1.0 + 0.4) * 0.3 + M_PI * 0.09;
  const double chords_cut = 4 * 0.09 * (M_PI / 4 - std::sin(M_PI / 4));  // two chords a corner
  EXPECT_NEAR(grown.signed_area(), rounded_area - chords_cut, 1e-12);
}

TEST(FreeSpace, InTheOpenTheDistanceIsStraight) {
  const FreeSpace space({}, kFloor);
  EXPECT_DOUBLE_EQ(space.distance(point(0, 0), point(3, 4)), 5.0);
  EXPECT_DOUBLE_EQ(space.distance(point(0, 0), Polygon::from_rect({{2, -1}, {3, 1}})), 2.0);
}

TEST(FreeSpace, AnObstacleInTheWayIsWalkedAroundItsCorners) {
  const FreeSpace space({Polygon::from_rect({{-1, -1}, {1, 1}})}, kFloor);
  EXPECT_FALSE(space.free({-3, 0}, {3, 0}));
  EXPECT_TRUE(space.free({-3, 1}, {3, 1}));  // along an edge is not through it
  EXPECT_NEAR(space.distance(point(-3, 0), point(3, 0)), 2 * std::sqrt(5.0) + 2, 1e-12);
}

TEST(FreeSpace, AWallWithADoorwayIsCrossedThroughTheDoorway) {
  // A wall along x = 0 from y = -10 to 10 with a gap between y = 3 and y = 4.
  const FreeSpace space({Polygon::from_rect({{-0.1, -10}, {0.1, 3}}), Polygon::from_rect({{-0.1, 4}, {0.1, 10}})}, kFloor);
  const double expected = std::hypot(1.9, 3) + 0.2 + std::hypot(1.9, 3);  // (-2,0) to (-0.1,3), (0.1,3), (2,0)
  EXPECT_NEAR(space.distance(point(-2, 0), point(2, 0)), expected, 1e-12);
}

TEST(FreeSpace, NoWayOutIsInfinitelyFar) {
  // A closed box around the start, of walls that overlap as grown walls do.
  const FreeSpace space({Polygon::from_rect({{-2, -2}, {2, -1}}), Polygon::from_rect({{-2, 1}, {2, 2}}),
                         Polygon::from_rect({{-2, -1.5}, {-1, 1.5}}), Polygon::from_rect({{1, -1.5}, {2, 1.5}})},
                        kFloor);
  EXPECT_TRUE(std::isinf(space.distance(point(0, 0), point(5, 5))));
}

// A region half inside an obstacle is reached at its free part, where the obstacle's edge crosses it.
TEST(FreeSpace, ARegionPartlyInsideAnObstacleIsReachedAtItsFreePart) {
  const FreeSpace space({Polygon::from_rect({{-1, -1}, {1, 1}})}, kFloor);
  const Polygon region = Polygon::from_rect({{0.5, -0.5}, {1.5, 0.5}});  // sticks out of the right side
  EXPECT_NEAR(space.distance(point(3, 0), region), 1.5, 1e-12);  // straight in
  // From the left: round the obstacle's corners (-1, 1) and (1, 1), then down its side to (1, 0.5).
  EXPECT_NEAR(space.distance(point(-3, 0), region), std::sqrt(5.0) + 2 + 0.5, 1e-12);
}

}  // namespace
}  // namespace physltl::geometry
