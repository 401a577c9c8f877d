#pragma once
// The convex hull of a set of points in the plane.

#include "physltl/geometry/shapes.h"

#include <span>

namespace physltl::geometry {

// Counter-clockwise from the lowest-then-leftmost point, without collinear points. Fewer than three
// distinct points give those points (a degenerate hull: a point or a segment).
Polygon convex_hull(std::span<const Vec2> points);

}  // namespace physltl::geometry
