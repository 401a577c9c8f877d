#include "physltl/geometry/rect_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

namespace physltl::geometry {
namespace {

// Within `reach` of `p` in x and in y: the promise near() keeps.
bool within(const Rect& r, const Vec2& p, double reach) {
  return p.x() >= r.min.x() - reach && p.x() <= r.max.x() + reach && p.y() >= r.min.y() - reach &&
         p.y() <= r.max.y() + reach;
}

TEST(RectGrid, NearListsEveryRectangleWithinReachInAscendingOrder) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(0.0, 20.0), extent(0.05, 3.0);
  std::vector<Rect> rects;
  for (int i = 0; i < 150; ++i) {
    const Vec2 lo(coordinate(random), coordinate(random) / 3);
    rects.push_back({lo, lo + Vec2(extent(random), extent(random))});
  }
  const double reach = 0.45;
  const RectGrid grid(rects, reach);
  size_t listed = 0, needed = 0;
  std::uniform_real_distribution<double> query(-2.0, 25.0);
  for (int q = 0; q < 5000; ++q) {
    const Vec2 p(query(random), query(random) / 3);
    const auto near = grid.near(p);
    EXPECT_TRUE(std::is_sorted(near.begin(), near.end()));
    for (size_t i = 0; i < rects.size(); ++i) {
      if (!within(rects[i], p, reach)) continue;
      ++needed;
      EXPECT_TRUE(std::binary_search(near.begin(), near.end(), static_cast<int>(i))) << "rect " << i << " at " << p.transpose();
    }
    listed += near.size();
  }
  // And it is worth having: far fewer candidates than a scan.
  EXPECT_LT(listed, 5000u * rects.size() / 4);
  EXPECT_GT(needed, 0u);
}

TEST(RectGrid, PointsOffTheGridGetEveryRectangle) {
  const std::vector<Rect> rects = {{{0, 0}, {1, 1}}, {{5, 5}, {6, 6}}};
  const RectGrid grid(rects, 0.5);
  EXPECT_EQ(grid.near({100, 100}).size(), 2u);
  EXPECT_EQ(grid.near({std::numeric_limits<double>::quiet_NaN(), 0}).size(), 2u);
  EXPECT_EQ(grid.near({0.5, 0.5}).size(), 1u);
}

TEST(RectGrid, AnEmptyGridHasNothingNear) {
  EXPECT_TRUE(RectGrid().near({0, 0}).empty());
  EXPECT_TRUE(RectGrid({}, 1.0).near({0, 0}).empty());
}

}  // namespace
}  // namespace physltl::geometry
