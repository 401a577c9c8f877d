#include "physltl/geometry/free_space.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace physltl::geometry {
namespace {

const Rect kFloor{{-10, -10}, {10, 10}};

Polygon point(double x, double y) { return Polygon{{Vec2(x, y)}}; }

// Distances are exact but for a nanometre at each corner passed (obstacles shrink by that much, so that
// touching ones leave a way between them), always on the short side.
constexpr double kExact = 1e-8;

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
  EXPECT_NEAR(space.distance(point(-3, 0), point(3, 0)), 2 * std::sqrt(5.0) + 2, kExact);
}

TEST(FreeSpace, AWallWithADoorwayIsCrossedThroughTheDoorway) {
  // A wall along x = 0 from y = -10 to 10 with a gap between y = 3 and y = 4.
  const FreeSpace space({Polygon::from_rect({{-0.1, -10}, {0.1, 3}}), Polygon::from_rect({{-0.1, 4}, {0.1, 10}})}, kFloor);
  const double expected = std::hypot(1.9, 3) + 0.2 + std::hypot(1.9, 3);  // (-2,0) to (-0.1,3), (0.1,3), (2,0)
  EXPECT_NEAR(space.distance(point(-2, 0), point(2, 0)), expected, kExact);
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
  EXPECT_NEAR(space.distance(point(-3, 0), region), std::sqrt(5.0) + 2 + 0.5, kExact);
}

// Two bodies exactly the robot's diameter apart: their grown outlines touch, and the robot's centre still
// fits through on the line where they touch (touching a boundary is allowed).
TEST(FreeSpace, ObstaclesThatTouchLeaveAWayOfNoWidthBetweenThem) {
  const FreeSpace space({Polygon::from_rect({{-1, -5}, {0, 5}}), Polygon::from_rect({{0, -5}, {1, 5}})}, kFloor);
  EXPECT_NEAR(space.distance(point(0, -6), point(0, 6)), 12.0, kExact);
  EXPECT_TRUE(space.free({0, -6}, {0, 6}));
}

TEST(FreeSpace, APointInsideAnObstacleIsNotFree) {
  const FreeSpace space({Polygon::from_rect({{-1, -1}, {1, 1}})}, kFloor);
  EXPECT_FALSE(space.free({0.5, 0.5}, {0.5, 0.5}));
  EXPECT_TRUE(space.free({1, 0.5}, {1, 0.5}));  // on its boundary
  EXPECT_TRUE(std::isinf(space.distance(point(0.5, 0.5), point(5, 5))));
}

// A path that bends round the far side of a wall it first passes: a corner in the shadow of another.
TEST(FreeSpace, AWayRoundTwoCornersInTurnIsFound) {
  // A hook: a wall along y = 0 from x = -4 to 4 and one down from its right end to y = -4.
  const FreeSpace space({Polygon::from_rect({{-4, -0.1}, {4, 0.1}}), Polygon::from_rect({{3.9, -4}, {4.1, 0.1}})}, kFloor);
  // From above the wall's middle to under it, next to the hook's inner side: round (4.1, 0.1), (4.1, -4),
  // then (3.9, -4).
  const double expected = std::hypot(4.1, 1.9) + 4.1 + 0.2 + std::hypot(0.4, 0.5);
  EXPECT_NEAR(space.distance(point(0, 2), point(3.5, -3.5)), expected, kExact);
  EXPECT_LE(space.distance(point(0, 2), point(3.5, -3.5)), expected);  // a lower bound stays one
}

// Corners all along an aisle between two columns of boxes in a straight line: the way down the aisle is
// straight, and no pair of them is needed to find it.
TEST(FreeSpace, DownAnAisleBetweenRowsOfBoxesTheWayIsStraight) {
  std::vector<Polygon> boxes;
  for (int row = 0; row < 30; ++row) {
    for (double x : {-1.5, 1.5}) boxes.push_back(grown_from_inside(OrientedBox{{{x, -7.25 + 0.5 * row}, 0.0}, {1.0, 0.2}}, 0.25));
  }
  const FreeSpace space(boxes, kFloor);
  EXPECT_NEAR(space.distance(point(0, -9), point(0, 9)), 18.0, 1e-9);
  // From beside the middle of the left column to beside the middle of the right one: up the left column's
  // side to its top corner (-2.75, 7.45), round its two chords to (-2.5, 7.7), across, and down the same way.
  const double chord = 2 * 0.25 * std::sin(M_PI / 8);
  EXPECT_NEAR(space.distance(point(-2.8, 0), point(2.8, 0)), 2 * (std::hypot(0.05, 7.45) + 2 * chord) + 5.0, kExact);
}

// Over random fields of boxes that overlap, touch and cross the places: a path from A to B is as long as
// one from B to A (two searches from different roots agree), never shorter than the straight line between
// the places, and a place is at distance 0 from itself when any of it is free.
TEST(FreeSpace, DistancesAgreeBothWaysAndAreNeverShorterThanStraight) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int world = 0; world < 60; ++world) {
    std::vector<Polygon> obstacles;
    for (int i = 0; i < 40; ++i) {
      const OrientedBox box{{{20 * unit(random) - 10, 20 * unit(random) - 10}, world % 2 ? 3.2 * unit(random) : 0.0},
                            {0.1 + 2 * unit(random), 0.1 + 0.6 * unit(random)}};
      obstacles.push_back(grown_from_inside(box, 0.25));
    }
    std::vector<Polygon> places{point(20 * unit(random) - 10, 20 * unit(random) - 10)};
    for (int p = 0; p < 4; ++p) {
      const Vec2 centre(20 * unit(random) - 10, 20 * unit(random) - 10);
      places.push_back(Polygon::from_rect({centre - Vec2(1.0, 0.6), centre + Vec2(1.0, 0.6)}));
    }
    const FreeSpace space(obstacles, kFloor);
    const auto lengths = space.distances(places);
    for (size_t i = 0; i < places.size(); ++i) {
      for (size_t j = 0; j < places.size(); ++j) {
        SCOPED_TRACE(::testing::Message() << "world " << world << " from " << i << " to " << j);
        if (std::isinf(lengths[i][j])) {
          EXPECT_TRUE(std::isinf(lengths[j][i]));
          continue;
        }
        EXPECT_NEAR(lengths[i][j], lengths[j][i], 1e-9 * (1 + lengths[i][j]));
        Vec2 a, b;
        EXPECT_GE(lengths[i][j], distance(places[i], places[j], a, b) - 1e-9);
        if (i == j) {
          EXPECT_EQ(lengths[i][j], 0.0);
        }
      }
    }
  }
}

TEST(FreeSpace, ATimeLimitStopsTheDistances) {
  const FreeSpace space({Polygon::from_rect({{-1, -1}, {1, 1}})}, kFloor);
  const base::Deadline passed = base::Deadline::in(0.0);
  EXPECT_THROW(space.distances({point(-3, 0), point(3, 0)}, passed), base::DeadlineReached);
}

}  // namespace
}  // namespace physltl::geometry
