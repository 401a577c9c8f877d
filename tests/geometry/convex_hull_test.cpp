#include "physltl/geometry/convex_hull.h"

#include <gtest/gtest.h>

#include <vector>

namespace physltl::geometry {
namespace {

TEST(ConvexHull, KeepsTheCornersOfASquareCounterClockwiseAndDropsInnerAndCollinearPoints) {
  const std::vector<Vec2> points = {{1, 1}, {0, 0}, {2, 0}, {1, 0}, {2, 2}, {0, 2}, {0.5, 1.5}, {2, 1}};
  const Polygon hull = convex_hull(points);
  const std::vector<Vec2> expected = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_EQ(hull.vertices, expected);
  EXPECT_DOUBLE_EQ(hull.signed_area(), 4.0);
}

TEST(ConvexHull, OfATrapezoidSeenInPerspectiveIsThatTrapezoid) {
  // The floor's corners and the walls' tops of a picture: the hull is the outline around both.
  const std::vector<Vec2> points = {{-3, 0}, {3, 0}, {2, 4}, {-2, 4}, {-3, -1}, {3, -1}, {2, 3}, {-2, 3}};
  const Polygon hull = convex_hull(points);
  const std::vector<Vec2> expected = {{-3, -1}, {3, -1}, {3, 0}, {2, 4}, {-2, 4}, {-3, 0}};
  EXPECT_EQ(hull.vertices, expected);
}

TEST(ConvexHull, OfFewerThanThreeDistinctPointsIsThosePoints) {
  EXPECT_TRUE(convex_hull(std::vector<Vec2>{}).vertices.empty());
  EXPECT_EQ(convex_hull(std::vector<Vec2>{{1, 1}, {1, 1}}).vertices.size(), 1u);
  EXPECT_EQ(convex_hull(std::vector<Vec2>{{0, 0}, {1, 1}, {0, 0}}).vertices.size(), 2u);
}

}  // namespace
}  // namespace physltl::geometry
