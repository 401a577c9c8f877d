#pragma once
// What each kind of shape is to the geometry, one row per kind (as Box2D keeps a shape type's functions
// together): shape.cpp and free_space.cpp ask the row of a shape's kind instead of switching on it, so a
// new kind of body is one more row here (and one in each module's own table: docs/architecture.md).

#include "physltl/geometry/shape.h"

#include <optional>
#include <vector>

namespace physltl::geometry {

struct ShapeKindGeometry {
  double (*area)(const Shape& shape);
  // The radius of the largest disc about the centre inside the shape.
  double (*centre_clearance)(const Shape& shape);
  double (*distance)(const Shape& shape, const Pose2& pose, const Vec2& p);
  // The shape as a disc or as an oriented box, for the exact tests those allow; nothing for another kind.
  std::optional<double> (*disc_radius)(const Shape& shape);
  std::optional<OrientedBox> (*oriented_box)(const Shape& shape, const Pose2& pose);
  Rect (*bounds)(const Shape& shape, const Pose2& pose);
  std::vector<Polygon> (*convex_parts_at)(const Shape& shape, const Pose2& pose, CircleAs circle);
  bool (*contains_as_parts)(const Shape& shape, const Pose2& pose, const Vec2& p, CircleAs circle);
  Shape (*grown)(const Shape& shape, double by);
  // The robot's centre grown round the placed shape from inside (free_space.h).
  std::vector<Polygon> (*grown_from_inside)(const Shape& shape, const Pose2& pose, double radius);
};

const ShapeKindGeometry& kind_of(const Shape& shape);

// A convex polygon, counter-clockwise: 0 inside or on it.
double distance_to_convex(const Polygon& polygon, const Vec2& p);

}  // namespace physltl::geometry
