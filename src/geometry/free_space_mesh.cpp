#include "free_space_mesh.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>

namespace physltl::geometry {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Grown bodies overlap one another and places cross them: the predicates are exact, and the crossings are
// worked out in floating point (off by a rounding, far less than the seams below; exact constructions cost
// a third more of a small world's preparation and two thirds more of a big one's).
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Point = Kernel::Point_2;

Point point(const Vec2& v) { return {v.x(), v.y()}; }
Vec2 vec(const Point& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

void insert_outline(Cdt& cdt, const std::vector<Vec2>& vertices) {
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vec2& a = vertices[i];
    const Vec2& b = vertices[i + 1 == vertices.size() ? 0 : i + 1];
    if (a != b) cdt.insert_constraint(point(a), point(b));
  }
}

// Whether `centre`, the centroid of a face of the triangulation (so never on a constraint), lies inside the
// convex counter-clockwise polygon: by plain side tests where the answer is clear by a wide margin, by
// exact ones where it is not.
bool inside_convex(const Polygon& polygon, const Vec2& centre) {
  const auto& v = polygon.vertices;
  bool clear = true;
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec2 edge = v[i + 1 == v.size() ? 0 : i + 1] - v[i];
    const double side = cross(edge, centre - v[i]);
    const double margin = 1e-9 * edge.norm() * (1.0 + (centre - v[i]).norm());
    if (side < -margin) return false;
    if (side <= margin) clear = false;
  }
  if (clear) return true;
  for (size_t i = 0; i < v.size(); ++i) {
    if (CGAL::orientation(point(v[i]), point(v[i + 1 == v.size() ? 0 : i + 1]), point(centre)) != CGAL::LEFT_TURN) return false;
  }
  return true;
}

// Obstacles that touch leave a way of no width between them, which a path may take (touching a boundary
// is allowed): each obstacle shrunk towards its middle by kSeam, so that the way is a triangle's width.
constexpr double kSeam = 1e-9;

Polygon shrunk(const Polygon& obstacle) {
  Vec2 middle = Vec2::Zero();
  for (const Vec2& v : obstacle.vertices) middle += v;
  middle /= static_cast<double>(obstacle.vertices.size());
  Polygon inner;
  for (const Vec2& v : obstacle.vertices) {
    const double away = (v - middle).norm();
    inner.vertices.push_back(away > kSeam ? Vec2(v + (middle - v) * (kSeam / away)) : v);
  }
  return inner;
}

// The bounds, the obstacles shrunk and the places as constraints; the places of one point as vertices.
std::vector<Polygon> insert_constraints(Cdt& cdt, const std::vector<Polygon>& obstacles, const Rect& bounds,
                                        const std::vector<Polygon>& places, std::vector<Cdt::Vertex_handle>& point_places,
                                        const base::Deadline& deadline) {
  insert_outline(cdt, Polygon::from_rect(bounds).vertices);
  std::vector<Polygon> inner;
  inner.reserve(obstacles.size());
  for (size_t i = 0; i < obstacles.size(); ++i) {
    if (i % 64 == 0) deadline.check();
    inner.push_back(shrunk(obstacles[i]));
    insert_outline(cdt, inner.back().vertices);
  }
  point_places.assign(places.size(), {});
  for (size_t p = 0; p < places.size(); ++p) {
    const auto& v = places[p].vertices;
    if (v.size() == 1) point_places[p] = cdt.insert(point(v[0]));
    if (v.size() >= 3) insert_outline(cdt, v);
  }
  deadline.check();
  return inner;
}

// The free faces become the mesh's triangles (numbered in their info, -1 for the rest), each with the
// places that hold it.
void keep_free_faces(Cdt& cdt, const std::vector<Polygon>& inner, const std::function<const std::vector<int>&(const Vec2&)>& obstacles_at,
                     const Rect& bounds, const std::vector<Polygon>& places, FreeMesh& mesh, const base::Deadline& deadline) {
  std::vector<std::vector<Point>> outlines(places.size());
  for (size_t p = 0; p < places.size(); ++p) {
    if (places[p].vertices.size() < 3) continue;
    for (const Vec2& corner : places[p].vertices) outlines[p].push_back(point(corner));
  }
  mesh.place_triangles.assign(places.size(), {});
  int counted = 0;
  for (auto f : cdt.all_face_handles()) {
    f->info() = -1;
    if (cdt.is_infinite(f)) continue;
    if (++counted % 4096 == 0) deadline.check();
    const Vec2 centre = (mesh.vertices[static_cast<size_t>(f->vertex(0)->info())] + mesh.vertices[static_cast<size_t>(f->vertex(1)->info())] +
                         mesh.vertices[static_cast<size_t>(f->vertex(2)->info())]) / 3.0;
    if (centre.x() <= bounds.min.x() || centre.x() >= bounds.max.x() || centre.y() <= bounds.min.y() || centre.y() >= bounds.max.y()) continue;
    const std::vector<int>& near = obstacles_at(centre);
    if (std::any_of(near.begin(), near.end(), [&](int o) { return inside_convex(inner[static_cast<size_t>(o)], centre); })) {
      continue;
    }
    const int index = static_cast<int>(mesh.triangles.size());
    f->info() = index;
    FreeMesh::Triangle t;
    for (int e = 0; e < 3; ++e) t.vertex[static_cast<size_t>(e)] = f->vertex(e)->info();
    mesh.triangles.push_back(t);
    mesh.triangle_places.emplace_back();
    for (size_t p = 0; p < places.size(); ++p) {
      if (outlines[p].empty()) continue;
      const Rect r = places[p].bounds();
      if (centre.x() < r.min.x() - 1e-9 || centre.x() > r.max.x() + 1e-9 || centre.y() < r.min.y() - 1e-9 || centre.y() > r.max.y() + 1e-9) continue;
      if (CGAL::bounded_side_2(outlines[p].begin(), outlines[p].end(), point(centre), Kernel()) == CGAL::ON_BOUNDED_SIDE) {
        mesh.place_triangles[p].push_back(index);
        mesh.triangle_places.back().push_back(static_cast<int>(p));
      }
    }
  }
}

// Neighbours across each edge (edge e of a face is the one opposite its vertex e + 2), the corners, and
// the triangles round each vertex.
void link_triangles(const Cdt& cdt, FreeMesh& mesh) {
  mesh.corner.assign(mesh.vertices.size(), 0);
  for (auto f : cdt.all_face_handles()) {
    if (f->info() < 0) {
      for (int i = 0; i < 3; ++i) {
        if (!cdt.is_infinite(f->vertex(i))) mesh.corner[static_cast<size_t>(f->vertex(i)->info())] = 1;
      }
      continue;
    }
    FreeMesh::Triangle& t = mesh.triangles[static_cast<size_t>(f->info())];
    for (int e = 0; e < 3; ++e) {
      const auto other = f->neighbor((e + 2) % 3);
      t.neighbour[static_cast<size_t>(e)] = other->info();
      t.neighbour_edge[static_cast<size_t>(e)] = other->info() < 0 ? -1 : (other->index(f) + 1) % 3;
    }
  }
  mesh.incident_start.assign(mesh.vertices.size() + 1, 0);
  for (const auto& t : mesh.triangles) {
    for (int v : t.vertex) ++mesh.incident_start[static_cast<size_t>(v) + 1];
  }
  for (size_t v = 0; v < mesh.vertices.size(); ++v) mesh.incident_start[v + 1] += mesh.incident_start[v];
  mesh.incident.resize(static_cast<size_t>(mesh.incident_start.back()));
  std::vector<int> filled(mesh.incident_start.begin(), mesh.incident_start.end() - 1);
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (int v : mesh.triangles[i].vertex) mesh.incident[static_cast<size_t>(filled[static_cast<size_t>(v)]++)] = static_cast<int>(i);
  }
}

}  // namespace

FreeMesh triangulate_free_space(const std::vector<Polygon>& obstacles,
                                const std::function<const std::vector<int>&(const Vec2&)>& obstacles_at, const Rect& bounds,
                                const std::vector<Polygon>& places, const base::Deadline& deadline) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> point_places;
  const std::vector<Polygon> inner = insert_constraints(cdt, obstacles, bounds, places, point_places, deadline);
  FreeMesh mesh;
  int next = 0;
  for (auto v : cdt.finite_vertex_handles()) {
    v->info() = next++;
    mesh.vertices.push_back(vec(v->point()));
  }
  keep_free_faces(cdt, inner, obstacles_at, bounds, places, mesh, deadline);
  link_triangles(cdt, mesh);
  mesh.place_vertex.assign(places.size(), -1);
  mesh.point_place_at.assign(mesh.vertices.size(), 0);
  for (size_t p = 0; p < places.size(); ++p) {
    if (places[p].vertices.size() != 1) continue;
    const auto v = static_cast<size_t>(point_places[p]->info());
    if (mesh.incident_start[v + 1] == mesh.incident_start[v]) continue;  // not free
    mesh.place_vertex[p] = static_cast<int>(v);
    mesh.point_place_at[v] = 1;
  }
  return mesh;
}

}  // namespace physltl::geometry
