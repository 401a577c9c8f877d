// libFuzzer target: the bytes are an OBJ file, as a scenario's `fixed { mesh = ... }` names one. read_obj
// must return a mesh or throw MeshError, and the footprint of what it returns must be computed (CGAL's
// union and decomposition included); anything else (a crash, a sanitizer report, another exception, a
// hang) is a bug.

#include "physltl/geometry/mesh.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = "/tmp/physltl-obj-fuzz-" + std::to_string(getpid()) + ".obj";
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    const physltl::geometry::Mesh mesh = physltl::geometry::read_obj(path);
    if (mesh.triangles.size() <= 2000) physltl::geometry::floor_footprint(mesh, 1.0, 0.5);
  } catch (const physltl::geometry::MeshError&) {
  }
  return 0;
}
