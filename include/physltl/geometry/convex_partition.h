#pragma once
// Convex pieces of polygons, for the physics (ODE collides convex shapes) and for every exact query
// (geometry::Shape), and the outline of a union of pieces (a body authored as parts). CGAL does the work:
// Hertel and Mehlhorn's partition for a simple polygon (at most four times the fewest pieces), a vertical
// decomposition for the union of many polygons, holes and all, and its Boolean set operations.

#include "physltl/geometry/shapes.h"

#include <optional>
#include <vector>

namespace physltl::geometry {

// Convex polygons, counter-clockwise, that tile the simple polygon `polygon` (itself when it is convex).
std::vector<Polygon> convex_partition(const Polygon& polygon);

// Convex polygons that tile the union of `polygons` (any orientation, may overlap or touch; degenerate
// ones add nothing); empty when the union has no area.
std::vector<Polygon> convex_partition_of_union(const std::vector<Polygon>& polygons);

// The outline of the union of `polygons`, counter-clockwise, without corners where it goes straight on;
// nothing when the union is not one simple polygon (pieces apart or meeting at a corner only, a hole) or a
// polygon is degenerate.
std::optional<Polygon> union_outline(const std::vector<Polygon>& polygons);

// Whether a polygon (either orientation) is convex: every turn the same way, none backwards.
bool is_convex(const Polygon& polygon);

}  // namespace physltl::geometry
