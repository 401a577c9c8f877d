#pragma once
// Regions and mRegions are arbitrary simple polygons; OpenGL fills triangles.

#include "physltl/geometry/shapes.h"

#include <array>
#include <vector>

namespace physltl::render {

// Ear clipping: n - 2 triangles for a simple polygon with n vertices, in either orientation.
std::vector<std::array<geometry::Vec2, 3>> triangulate(const geometry::Polygon& polygon);

}  // namespace physltl::render
