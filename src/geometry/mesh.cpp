#include "physltl/geometry/mesh.h"

#include "physltl/geometry/convex_partition.h"

#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace physltl::geometry {
namespace {

using Eigen::Vector3d;

constexpr std::uintmax_t kMaxObjBytes = std::uintmax_t{64} << 20;

// The part of a triangle at or below z = top, as a polygon projected on the floor (empty when none).
Polygon below(const std::array<Vector3d, 3>& corners, double top) {
  Polygon out;
  for (size_t i = 0; i < 3; ++i) {
    const Vector3d& a = corners[i];
    const Vector3d& b = corners[(i + 1) % 3];
    const bool a_in = a.z() <= top, b_in = b.z() <= top;
    if (a_in) out.vertices.emplace_back(a.x(), a.y());
    if (a_in != b_in) {
      const double t = (top - a.z()) / (b.z() - a.z());
      const Vector3d c = a + t * (b - a);
      out.vertices.emplace_back(c.x(), c.y());
    }
  }
  return out;
}

// The text of the OBJ file at `path`, at most kMaxObjBytes: a device or a huge file is refused, not read
// until memory runs out.
std::string obj_text(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw MeshError("mesh '" + path + "' does not exist");
  if (!std::filesystem::is_regular_file(status)) throw MeshError("mesh '" + path + "' is not a regular file");
  if (std::filesystem::file_size(path, error) > kMaxObjBytes) {
    throw MeshError("mesh '" + path + "' is larger than " + std::to_string(kMaxObjBytes >> 20) + " MiB");
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw MeshError("mesh '" + path + "' cannot be read");
  return text.str();
}

// tinyobjloader reads leniently: "nan" or a missing coordinate as 0, a face of two corners or with an
// index past the vertices as nothing, silently. The lines this program uses (v, f) are checked first,
// so that a broken file is an error naming its line, not another shape.
void check_obj_lines(const std::string& text, const std::string& path) {
  std::istringstream lines(text);
  std::string line;
  long long vertices = 0;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    const auto refuse = [&](const std::string& why) {
      throw MeshError("mesh '" + path + "' line " + std::to_string(number) + ": " + why);
    };
    if (keyword == "v") {
      std::vector<std::string> coordinates{std::istream_iterator<std::string>(words), {}};
      if (coordinates.size() != 3 && coordinates.size() != 4 && coordinates.size() != 6) refuse("a vertex needs x, y and z");
      for (const std::string& c : coordinates) {
        char* end = nullptr;
        const double value = std::strtod(c.c_str(), &end);
        if (end != c.c_str() + c.size() || !std::isfinite(value)) refuse("a vertex coordinate '" + c + "' is not a finite number");
      }
      ++vertices;
    } else if (keyword == "f") {
      std::vector<std::string> corners{std::istream_iterator<std::string>(words), {}};
      if (corners.size() < 3) refuse("a face needs at least 3 corners");
      for (const std::string& corner : corners) {
        const std::string index = corner.substr(0, corner.find('/'));
        long long k = 0;
        const auto [end, error] = std::from_chars(index.data(), index.data() + index.size(), k);
        const bool defined = error == std::errc() && end == index.data() + index.size() && k != 0 &&
                             (k > 0 ? k <= vertices : -k <= vertices);
        if (!defined) refuse("a face corner '" + corner + "' names no vertex defined before it");
      }
    }
  }
}

}  // namespace

Mesh read_obj(const std::string& path) {
  const std::string text = obj_text(path);
  check_obj_lines(text, path);
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config)) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    throw MeshError("mesh '" + path + "' cannot be read: " + (why.empty() ? "not an OBJ file" : why));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto vertex = [&](const tinyobj::index_t& i) -> Vector3d {
    const auto k = static_cast<size_t>(i.vertex_index);
    if (i.vertex_index < 0 || 3 * k + 2 >= attrib.vertices.size()) {
      throw MeshError("mesh '" + path + "' has a face with a vertex it does not define");
    }
    return {attrib.vertices[3 * k], attrib.vertices[3 * k + 1], attrib.vertices[3 * k + 2]};
  };
  const auto normal = [&](const tinyobj::index_t& i) -> Vector3d {
    const auto k = static_cast<size_t>(i.normal_index);
    if (3 * k + 2 >= attrib.normals.size()) throw MeshError("mesh '" + path + "' has a face with a normal it does not define");
    return {attrib.normals[3 * k], attrib.normals[3 * k + 1], attrib.normals[3 * k + 2]};
  };
  Mesh mesh;
  bool every_normal = true;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    for (size_t f = 0; f + 2 < indices.size(); f += 3) {
      std::array<Vector3d, 3> corners{vertex(indices[f]), vertex(indices[f + 1]), vertex(indices[f + 2])};
      for (const Vector3d& c : corners) {
        if (!c.allFinite()) throw MeshError("mesh '" + path + "' has a vertex that is not a finite number");
      }
      mesh.triangles.push_back(corners);
      every_normal = every_normal && indices[f].normal_index >= 0 && indices[f + 1].normal_index >= 0 &&
                     indices[f + 2].normal_index >= 0;
      if (every_normal) mesh.normals.push_back({normal(indices[f]), normal(indices[f + 1]), normal(indices[f + 2])});
    }
  }
  if (!every_normal) mesh.normals.clear();
  if (mesh.triangles.empty()) throw MeshError("mesh '" + path + "' has no triangles");
  return mesh;
}

std::vector<Polygon> floor_footprint(const Mesh& mesh, double scale, double top) {
  std::vector<Polygon> shadows;
  shadows.reserve(mesh.triangles.size());
  for (const auto& triangle : mesh.triangles) {
    std::array<Vector3d, 3> scaled{scale * triangle[0], scale * triangle[1], scale * triangle[2]};
    Polygon shadow = below(scaled, top);
    if (shadow.vertices.size() >= 3 && std::abs(shadow.signed_area()) > 1e-12) shadows.push_back(std::move(shadow));
  }
  return convex_partition_of_union(shadows);
}

}  // namespace physltl::geometry
