#pragma once
// Triangle meshes from Wavefront OBJ files (tinyobjloader), in metres with z up, and what of a mesh stands
// on the floor: the footprint a fixed body collides with (scenario files' `fixed { mesh = ... }`).

#include "physltl/geometry/shapes.h"

#include <Eigen/Core>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace physltl::geometry {

struct Mesh {
  std::vector<std::array<Eigen::Vector3d, 3>> triangles;
  // Per triangle, the file's normal at each corner; empty when the file gives none.
  std::vector<std::array<Eigen::Vector3d, 3>> normals;
};

// Why a mesh file could not be used, in a sentence that names the file.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The file's faces as triangles. Throws MeshError when it cannot be read (not a regular file, over 64 MiB),
// has no triangles, or has a vertex that is not three finite numbers or a face of fewer than three corners
// or naming a vertex not defined before it (with the line).
Mesh read_obj(const std::string& path);

// The mesh scaled by `scale` about its origin, its floor projection of everything at or below height `top`
// (triangles cut at that height): convex polygons, in the mesh's own x and y, that tile it. A desk's
// top above the robot does not count; its legs do.
std::vector<Polygon> floor_footprint(const Mesh& mesh, double scale, double top);

}  // namespace physltl::geometry
