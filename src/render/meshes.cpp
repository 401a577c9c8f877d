#include "meshes.h"

#include "physltl/geometry/mesh.h"

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

TriangleMesh obj_mesh(const std::string& path, double scale) {
  const geometry::Mesh obj = geometry::read_obj(path);
  TriangleMesh mesh;
  for (std::size_t t = 0; t < obj.triangles.size(); ++t) {
    Vector3f p[3];
    for (int k = 0; k < 3; ++k) p[k] = (scale * obj.triangles[t][static_cast<std::size_t>(k)]).cast<float>();
    const Vector3f flat = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    for (int k = 0; k < 3; ++k) {
      add_vertex(mesh, p[k], obj.normals.empty() ? flat : obj.normals[t][static_cast<std::size_t>(k)].cast<float>().normalized());
    }
  }
  return mesh;
}

TriangleMesh cylinder_mesh(double radius, double height, int slices) {
  TriangleMesh mesh;
  const auto r = static_cast<float>(radius), h = static_cast<float>(height);
  for (int k = 0; k < slices; ++k) {
    const float a0 = 2.0f * std::numbers::pi_v<float> * k / slices, a1 = 2.0f * std::numbers::pi_v<float> * (k + 1) / slices;
    const Vector3f n0(std::cos(a0), std::sin(a0), 0), n1(std::cos(a1), std::sin(a1), 0);
    const Vector3f b0 = r * n0, b1 = r * n1, t0 = b0 + Vector3f(0, 0, h), t1 = b1 + Vector3f(0, 0, h);
    add_vertex(mesh, b0, n0), add_vertex(mesh, b1, n1), add_vertex(mesh, t1, n1);
    add_vertex(mesh, b0, n0), add_vertex(mesh, t1, n1), add_vertex(mesh, t0, n0);
    const Vector3f up(0, 0, 1), centre(0, 0, h);
    add_vertex(mesh, centre, up), add_vertex(mesh, t0, up), add_vertex(mesh, t1, up);
  }
  return mesh;
}

TriangleMesh prism_mesh(const std::vector<geometry::Polygon>& parts, double height) {
  TriangleMesh mesh;
  const auto h = static_cast<float>(height);
  for (const geometry::Polygon& part : parts) {  // convex, counter-clockwise
    const auto& v = part.vertices;
    const auto at = [&](std::size_t i, float z) { return Vector3f(static_cast<float>(v[i].x()), static_cast<float>(v[i].y()), z); };
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
      add_vertex(mesh, at(0, h), Vector3f::UnitZ()), add_vertex(mesh, at(i, h), Vector3f::UnitZ());
      add_vertex(mesh, at(i + 1, h), Vector3f::UnitZ());
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::size_t j = (i + 1) % v.size();
      const Vector3f n = Vector3f(static_cast<float>(v[j].y() - v[i].y()), static_cast<float>(v[i].x() - v[j].x()), 0).normalized();
      for (const Vector3f& p : {at(i, 0), at(j, 0), at(j, h), at(i, 0), at(j, h), at(i, h)}) add_vertex(mesh, p, n);
    }
  }
  return mesh;
}

}  // namespace physltl::render
