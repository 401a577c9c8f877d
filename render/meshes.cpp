#include "meshes.h"

#include <tiny_obj_loader.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace physltl::render {
namespace {

using Eigen::Vector3f;

void add_vertex(TriangleMesh& mesh, const Vector3f& p, const Vector3f& n) {
  mesh.insert(mesh.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()});
}

}  // namespace

TriangleMesh unit_cube_mesh() {
  TriangleMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      Vector3f n = Vector3f::Zero();
      n[axis] = sign;
      // u, v span the face so that u x v points along n: triangles come out counter-clockwise from outside.
      Vector3f u = Vector3f::Zero(), v = Vector3f::Zero();
      u[(axis + 1) % 3] = 0.5f;
      v[(axis + 2) % 3] = 0.5f * sign;
      const Vector3f c = 0.5f * n;
      const Vector3f corners[4] = {c - u - v, c + u - v, c + u + v, c - u + v};
      for (int i : {0, 1, 2, 0, 2, 3}) add_vertex(mesh, corners[i], n);
    }
  }
  return mesh;
}

TriangleMesh unit_sphere_mesh(int slices, int stacks) {
  auto point = [&](int slice, int stack) {
    const float theta = 2.0f * std::numbers::pi_v<float> * slice / slices;
    const float phi = std::numbers::pi_v<float> * stack / stacks;
    return Vector3f(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi));
  };
  TriangleMesh mesh;
  for (int stack = 0; stack < stacks; ++stack) {
    for (int slice = 0; slice < slices; ++slice) {
      const Vector3f a = point(slice, stack), b = point(slice, stack + 1);
      const Vector3f c = point(slice + 1, stack + 1), d = point(slice + 1, stack);
      for (const Vector3f& p : {a, b, c, a, c, d}) add_vertex(mesh, p, p);  // on a unit sphere, normal = point
    }
  }
  return mesh;
}

TriangleMesh load_obj_mesh(const std::string& path) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    throw std::runtime_error("cannot read mesh " + path + ": " + reader.Error());
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  auto position = [&](const tinyobj::index_t& i) {
    return Vector3f(attrib.vertices[3 * i.vertex_index], attrib.vertices[3 * i.vertex_index + 1],
                    attrib.vertices[3 * i.vertex_index + 2]);
  };
  TriangleMesh mesh;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    for (std::size_t f = 0; f + 2 < indices.size(); f += 3) {
      const Vector3f p[3] = {position(indices[f]), position(indices[f + 1]), position(indices[f + 2])};
      const Vector3f flat = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
      for (int k = 0; k < 3; ++k) {
        const tinyobj::index_t& i = indices[f + k];
        const Vector3f n = i.normal_index < 0
                               ? flat
                               : Vector3f(attrib.normals[3 * i.normal_index], attrib.normals[3 * i.normal_index + 1],
                                          attrib.normals[3 * i.normal_index + 2]);
        add_vertex(mesh, p[k], n);
      }
    }
  }
  if (mesh.empty()) throw std::runtime_error("mesh " + path + " has no triangles");
  return mesh;
}

}  // namespace physltl::render
