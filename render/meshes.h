#pragma once
// Triangle meshes as interleaved floats (x y z nx ny nz per vertex), in a body's own frame, z up.

#include <string>
#include <vector>

namespace physltl::render {

using TriangleMesh = std::vector<float>;

TriangleMesh unit_cube_mesh();                           // [-0.5, 0.5]^3
TriangleMesh unit_sphere_mesh(int slices, int stacks);   // radius 1, centred at the origin
// An OBJ file's triangles in metres, as authored; flat normals where the file has none.
// Throws std::runtime_error naming the file when it cannot be read.
TriangleMesh load_obj_mesh(const std::string& path);

}  // namespace physltl::render
