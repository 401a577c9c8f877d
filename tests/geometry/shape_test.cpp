// Footprints of every kind against analytic values: distance, containment, overlap, bounds, area; convex
// pieces of polygons and of a mesh's floor projection.

#include "physltl/geometry/convex_partition.h"
#include "physltl/geometry/mesh.h"
#include "physltl/geometry/shape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace physltl::geometry {
namespace {

constexpr double kPi = std::numbers::pi;

Polygon hexagon(double circumradius) {
  Polygon p;
  for (int k = 0; k < 6; ++k) p.vertices.push_back(circumradius * Vec2(std::cos(k * kPi / 3), std::sin(k * kPi / 3)));
  return p;
}

Shape convex(const Polygon& p) { return Shape::polygon(p, {p}); }

double total_area(const std::vector<Polygon>& parts) {
  double a = 0.0;
  for (const Polygon& p : parts) a += p.signed_area();
  return a;
}

bool covered(const std::vector<Polygon>& parts, const Vec2& p) {
  for (const Polygon& part : parts) {
    if (part.contains(p)) return true;
  }
  return false;
}

TEST(Shape, DistancesFromEachKindAreTheAnalyticOnes) {
  const Pose2 at{{2.0, 1.0}, kPi / 2};
  const Shape box = Shape::box({0.5, 0.25});  // turned a quarter turn: half extents 0.25 along world x, 0.5 along y
  EXPECT_DOUBLE_EQ(distance(box, at, {2.0, 1.0}), 0.0);
  EXPECT_NEAR(distance(box, at, {3.0, 1.0}), 0.75, 1e-12);   // half width 0.25 along world x
  EXPECT_NEAR(distance(box, at, {2.0, 2.0}), 0.5, 1e-12);    // half length 0.5 along world y
  EXPECT_NEAR(distance(box, at, {3.25, 2.5}), std::hypot(1.0, 1.0), 1e-12);

  const Shape disc = Shape::circle(0.3);
  EXPECT_NEAR(distance(disc, at, {2.0, 2.0}), 0.7, 1e-12);
  EXPECT_DOUBLE_EQ(distance(disc, at, {2.1, 1.1}), 0.0);
  EXPECT_NEAR(disc.area(), kPi * 0.09, 1e-12);

  // A regular hexagon of circumradius 1 has an inradius of sqrt(3)/2: that far from its centre to a side.
  const Shape hex = convex(hexagon(1.0));
  EXPECT_NEAR(distance(hex, {{0, 0}, 0.0}, {0.0, 2.0}), 2.0 - std::sqrt(3.0) / 2, 1e-12);
  EXPECT_NEAR(distance(hex, {{0, 0}, 0.0}, {3.0, 0.0}), 2.0, 1e-12);  // to the corner at (1, 0)
  EXPECT_NEAR(distance(hex, {{0, 0}, kPi / 6}, {3.0, 0.0}), 3.0 - std::sqrt(3.0) / 2, 1e-12);  // now a side
  EXPECT_NEAR(hex.area(), 1.5 * std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(hex.bound_radius(), 1.0, 1e-12);
}

TEST(Shape, OverlapsOfEveryPairOfKindsAreExact) {
  const Shape box = Shape::box({0.5, 0.5}), disc = Shape::circle(0.5), hex = convex(hexagon(0.5));
  const Pose2 origin{{0, 0}, 0.0};
  // Discs: centres 1 m apart touch, closer overlap.
  EXPECT_FALSE(overlap(disc, origin, disc, {{1.0, 0}, 0.0}));
  EXPECT_TRUE(overlap(disc, origin, disc, {{0.99, 0}, 0.0}));
  // A disc against a box's corner: overlap only once the corner is inside the disc.
  const double corner = std::sqrt(0.5);  // from the box's centre to its corner
  EXPECT_FALSE(overlap(box, origin, disc, {Vec2::Constant((corner + 0.5 + 0.01) / std::sqrt(2.0)), 0.0}));
  EXPECT_TRUE(overlap(box, origin, disc, {Vec2::Constant((corner + 0.5 - 0.01) / std::sqrt(2.0)), 0.0}));
  // A hexagon's flat side (inradius 0.433) against a box's side: they meet at 0.933 between centres.
  const Pose2 flat{{0.0, 0.0}, kPi / 6};  // a side faces +x
  const double inradius = 0.5 * std::sqrt(3.0) / 2;
  EXPECT_FALSE(overlap(hex, flat, box, {{0.5 + inradius + 0.001, 0}, 0.0}));
  EXPECT_TRUE(overlap(hex, flat, box, {{0.5 + inradius - 0.001, 0}, 0.0}));
  // The same hexagon corner-first reaches 0.5 m.
  EXPECT_TRUE(overlap(hex, origin, box, {{0.5 + 0.5 - 0.001, 0}, 0.0}));
  EXPECT_FALSE(overlap(hex, origin, box, {{0.5 + 0.5 + 0.001, 0}, 0.0}));
  // A disc (the robot) against each kind.
  EXPECT_TRUE(overlap(hex, flat, Vec2(inradius + 0.2, 0.0), 0.21));
  EXPECT_FALSE(overlap(hex, flat, Vec2(inradius + 0.2, 0.0), 0.19));
  EXPECT_TRUE(overlap(disc, origin, Vec2(0.7, 0.0), 0.21));
  EXPECT_FALSE(overlap(disc, origin, Vec2(0.7, 0.0), 0.19));
}

TEST(Shape, InsideAndBoundsFollowTheShapeNotItsBoundingCircle) {
  const Rect room{{0, 0}, {4, 3}};
  const Shape hex = convex(hexagon(1.0));
  // Corners at x = +-1 when unturned; sides at y = +-0.866.
  EXPECT_TRUE(inside(hex, {{1.0, 0.87}, 0.0}, room));
  EXPECT_FALSE(inside(hex, {{0.99, 1.5}, 0.0}, room));
  const Rect b = bounds(hex, {{2, 1.5}, 0.0});
  EXPECT_NEAR(b.min.x(), 1.0, 1e-12);
  EXPECT_NEAR(b.max.y(), 1.5 + std::sqrt(3.0) / 2, 1e-12);
  const Shape disc = Shape::circle(0.5);
  EXPECT_TRUE(inside(disc, {{0.5, 0.5}, 0.0}, room));
  EXPECT_FALSE(inside(disc, {{0.49, 0.5}, 0.0}, room));
}

TEST(Shape, ACircleAsPolygonLiesInsideOrOutsideItAsAsked) {
  const Shape disc = Shape::circle(1.0);
  const Polygon in = convex_parts_at(disc, {{0, 0}, 0.0}, CircleAs::kInscribed).front();
  const Polygon out = convex_parts_at(disc, {{0, 0}, 0.0}, CircleAs::kCircumscribed).front();
  for (const Vec2& v : in.vertices) EXPECT_NEAR(v.norm(), 1.0, 1e-12);
  EXPECT_LT(std::abs(in.signed_area()), kPi);
  EXPECT_GT(std::abs(out.signed_area()), kPi);
  // Its sides touch the circle: each side's middle is 1 m from the centre.
  for (size_t i = 0, j = out.vertices.size() - 1; i < out.vertices.size(); j = i++) {
    EXPECT_NEAR((0.5 * (out.vertices[i] + out.vertices[j])).norm(), 1.0, 1e-12);
  }
}

TEST(ConvexPartition, AnLShapeIsTiledByConvexPiecesOfItsArea) {
  const Polygon l{{{0, 0}, {2, 0}, {2, 0.6}, {0.6, 0.6}, {0.6, 1.5}, {0, 1.5}}};
  EXPECT_FALSE(is_convex(l));
  const std::vector<Polygon> parts = convex_partition(l);
  ASSERT_GE(parts.size(), 2u);
  for (const Polygon& p : parts) EXPECT_TRUE(is_convex(p));
  EXPECT_NEAR(total_area(parts), 2 * 0.6 + 0.6 * 0.9, 1e-12);
  EXPECT_TRUE(covered(parts, {1.5, 0.3}));
  EXPECT_TRUE(covered(parts, {0.3, 1.2}));
  EXPECT_FALSE(covered(parts, {1.0, 1.0}));  // the inner corner
  EXPECT_EQ(convex_partition(hexagon(1.0)).size(), 1u);
}

TEST(ConvexPartition, TheUnionOfOverlappingPolygonsHasTheUnionsArea) {
  const Polygon a = Polygon::from_rect({{0, 0}, {2, 1}}), b = Polygon::from_rect({{1, 0}, {3, 1}});
  const Polygon ring_hole = Polygon::from_rect({{10, 10}, {11, 11}});
  EXPECT_NEAR(total_area(convex_partition_of_union({a, b})), 3.0, 1e-12);
  // A square frame: four bars round a hole, whose middle stays uncovered.
  const std::vector<Polygon> frame = convex_partition_of_union(
      {Polygon::from_rect({{0, 0}, {3, 1}}), Polygon::from_rect({{0, 2}, {3, 3}}), Polygon::from_rect({{0, 0}, {1, 3}}),
       Polygon::from_rect({{2, 0}, {3, 3}}), ring_hole});
  EXPECT_NEAR(total_area(frame), 9.0 - 1.0 + 1.0, 1e-12);
  EXPECT_FALSE(covered(frame, {1.5, 1.5}));
  EXPECT_TRUE(covered(frame, {10.5, 10.5}));
}

TEST(Mesh, TheFootprintIsTheFloorProjectionOfWhatStandsBelowTheRobotsTop) {
  const Mesh desk = read_obj(std::string(PHYSLTL_SOURCE_DIR) + "/tests/geometry/data/l_desk.obj");
  // Below 0.5 m: the two panels, 1.8 x 0.1 and 0.1 x 1.3, as an L that leaves the inner corner free.
  const std::vector<Polygon> low = floor_footprint(desk, 1.0, 0.5);
  EXPECT_NEAR(total_area(low), 1.8 * 0.1 + 0.1 * 1.3, 1e-6);
  EXPECT_TRUE(covered(low, {1.0, 0.05}));
  EXPECT_TRUE(covered(low, {0.05, 1.0}));
  EXPECT_FALSE(covered(low, {1.0, 1.0}));
  EXPECT_FALSE(covered(low, {1.0, 0.3}));  // under the top, beside the panel
  // Up to 1 m the top counts too: the L of the whole desk (OBJ coordinates are read as floats).
  EXPECT_NEAR(total_area(floor_footprint(desk, 1.0, 1.0)), 2 * 0.6 + 0.6 * 0.9, 1e-6);
  // Scaled by 2 about its origin, heights too: below 1 m only the panels, four times as large.
  EXPECT_NEAR(total_area(floor_footprint(desk, 2.0, 1.0)), 4 * (1.8 * 0.1 + 0.1 * 1.3), 1e-6);
  EXPECT_NEAR(total_area(floor_footprint(desk, 2.0, 2.0)), 4 * (2 * 0.6 + 0.6 * 0.9), 1e-6);
}

TEST(Mesh, AFileThatIsNotAMeshIsAClearError) {
  const std::string data = std::string(PHYSLTL_SOURCE_DIR) + "/tests/geometry/data/";
  for (const char* name : {"missing.obj", "not_a_mesh.obj", "no_faces.obj", "broken_index.obj"}) {
    try {
      read_obj(data + name);
      ADD_FAILURE() << name << " was read";
    } catch (const MeshError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace physltl::geometry
