#include "physltl/geometry/disc_field.h"

#include "physltl/geometry/free_space.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace physltl::geometry {
namespace {

const Rect kBounds{Vec2(0, 0), Vec2(10, 6)};

// Slanted quadrilaterals scattered over the bounds, some reaching past its edge.
std::vector<Polygon> scattered_regions(int count) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> x(-0.5, 10.5), y(-0.5, 6.5), size(0.05, 0.8);
  std::vector<Polygon> regions;
  for (int i = 0; i < count; ++i) {
    const Vec2 at(x(random), y(random));
    const double a = size(random), b = size(random);
    regions.push_back({{at, at + Vec2(a, 0.2 * b), at + Vec2(a, b), at + Vec2(-0.1 * a, b)}});
  }
  return regions;
}

// cells_near finds each region's cells from its bounding box: the same cells as testing every cell against
// every region, inside a region (0) and within a distance of one.
TEST(DiscField, CellsNearRegionsAreTheCellsEveryRegionTestedAtEveryCellWouldGive) {
  const std::vector<Polygon> regions = scattered_regions(60);
  std::vector<const Polygon*> pointers;
  for (const Polygon& r : regions) pointers.push_back(&r);
  const DiscField field(kBounds, 0.1, 0.2, {});
  const UniformGrid grid = UniformGrid::covering(kBounds, 0.1);
  for (const double within : {0.0, 0.07}) {
    const std::vector<bool> near = field.cells_near(pointers, within);
    ASSERT_EQ(near.size(), grid.size());
    int marked = 0;
    for (int row = 0; row < grid.rows(); ++row) {
      for (int column = 0; column < grid.columns(); ++column) {
        const Vec2 centre = grid.centre(column, row);
        bool expected = false;
        for (const Polygon& r : regions) expected = expected || (within > 0.0 ? distance(centre, r) <= within : r.contains(centre));
        EXPECT_EQ(near[grid.index(column, row)], expected) << "within " << within << " at " << centre.transpose();
        marked += expected;
      }
    }
    EXPECT_GT(marked, 100) << within;  // the regions cover cells, not nothing
  }
}

// A field of a million cells takes a while: a deadline that has come stops it being made or searched.
TEST(DiscField, ADeadlineThatHasComeStopsTheFieldAndItsDistances) {
  const base::Deadline passed = base::Deadline::in(0.0);
  const std::vector<Footprint> wall{{Pose2{Vec2(5, 3), 0.0}, Shape::box(Vec2(0.1, 2.0))}};
  EXPECT_THROW(DiscField(kBounds, 0.01, 0.2, wall, passed), base::DeadlineReached);
  DiscField field(kBounds, 0.01, 0.2, wall);
  const Polygon goal = Polygon::from_rect({Vec2(8, 2), Vec2(9, 3)});
  const std::vector<const Polygon*> goals{&goal};
  EXPECT_THROW(field.cells_near(goals, 0.0, passed), base::DeadlineReached);
  const std::vector<bool> targets = field.cells_near(goals, 0.0);
  EXPECT_THROW(field.compute_distances(targets, passed), base::DeadlineReached);
  field.compute_distances(targets);  // without one: the way round the wall
  EXPECT_TRUE(field.reaches_target(Vec2(1, 1)));
  EXPECT_GT(field.distance(Vec2(1, 3)), 7.0);
}

}  // namespace
}  // namespace physltl::geometry
