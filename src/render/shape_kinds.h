#pragma once
// What each kind of shape looks like, one row per kind (geometry/shape_kinds.h has the geometry's): its
// mesh and its shadow. A new kind of body is one more row here.

#include "meshes.h"

#include "physltl/geometry/shape.h"

#include <optional>
#include <vector>

namespace physltl::render {

// A rounded rectangle under a body, in the floor's frame.
struct ShadowShape {
  geometry::Pose2 pose;
  geometry::Vec2 half_extents = geometry::Vec2::Zero();
  double corner_radius = 0.0;
};

struct ShapeKindDrawing {
  // The body as the unit cube scaled by (x, y, z) sizes, where it is one (a box): cheaper than a mesh of its own.
  std::optional<geometry::Vec2> (*as_cube)(const geometry::Shape& shape);
  // Its own mesh on the floor, `height` tall, in its frame: made once a shape.
  TriangleMesh (*mesh)(const geometry::Shape& shape, double height);
  // One shadow, or one per convex part of a concave polygon (the bounds of its parts: an L's notch
  // stays lit).
  std::vector<ShadowShape> (*shadows)(const geometry::Shape& shape, const geometry::Pose2& pose);
};

const ShapeKindDrawing& kind_of(const geometry::Shape& shape);

}  // namespace physltl::render
