#pragma once
// Triangle meshes as interleaved floats (x y z nx ny nz per vertex), in a body's own frame, z up.

#include "physltl/geometry/shapes.h"

#include <string>
#include <vector>

namespace physltl::render {

using TriangleMesh = std::vector<float>;

TriangleMesh unit_cube_mesh();                           // [-0.5, 0.5]^3
TriangleMesh unit_sphere_mesh(int slices, int stacks);   // radius 1, centred at the origin
// An OBJ file's triangles in metres, scaled by `scale` about its origin; flat normals where the file has
// none. Throws geometry::MeshError naming the file when it cannot be read.
TriangleMesh obj_mesh(const std::string& path, double scale);
// An upright cylinder on the floor (z from 0 to `height`), open at the bottom.
TriangleMesh cylinder_mesh(double radius, double height, int slices);
// Prisms on the floor over convex, counter-clockwise polygons, open at the bottom.
TriangleMesh prism_mesh(const std::vector<geometry::Polygon>& parts, double height);

}  // namespace physltl::render
