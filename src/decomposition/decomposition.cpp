#include "physltl/decomposition/decomposition.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "physltl/geometry/point_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace physltl::decomposition {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
// Walls touch and overlap each other's edges and region edges may cross walls: exact constructions
// keep the constraint intersections exact.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Default, CGAL::Exact_intersections_tag>;
using Point = Kernel::Point_2;

Point point(const Vec2& v) { return {v.x(), v.y()}; }
Vec2 vec(const Point& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

// Each edge goes in as pieces no longer than `max_piece`, so no triangle along a wall gets longer edges.
void insert_polygon(Cdt& cdt, const std::vector<Vec2>& vertices, double max_piece) {
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vec2 a = vertices[i], b = vertices[(i + 1) % vertices.size()];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / max_piece)));
    for (int k = 0; k < pieces; ++k) {
      cdt.insert_constraint(point(a + (b - a) * (double(k) / pieces)), point(a + (b - a) * (double(k + 1) / pieces)));
    }
  }
}

using geometry::cross;

bool triangle_contains(const Triangle& t, const Vec2& p) {
  const auto& c = t.corners;
  const double d0 = cross(c[1] - c[0], p - c[0]);
  const double d1 = cross(c[2] - c[1], p - c[1]);
  const double d2 = cross(c[0] - c[2], p - c[2]);
  const double eps = -1e-12;
  return (d0 >= eps && d1 >= eps && d2 >= eps) || (d0 <= -eps && d1 <= -eps && d2 <= -eps);
}

// Where the robot's centre would touch a movable body that stands in clutter: not a hole (the robot may
// push the body), but edges of the mesh, so that each triangle is clear of such a body or under it, and the
// lanes between the rows are triangles of their own. In clutter: another movable body within the robot's
// diameter (a row, a heap), and no fixed body that near. A body beside a wall stands in a passage: its
// outline would only cut slivers against the wall (tiny triangles the lead shuns), and the way there is
// through it anyway; a lone body has open floor round it, which the plain mesh already resolves.
std::vector<geometry::Polygon> clutter_outlines(const scenario::World& world) {
  const double r = world.robot.radius;
  const auto& bodies = world.movable_bodies;
  std::vector<Vec2> centres;
  double reach = 0.0;  // of a body's corners from its centre, the farthest
  for (const auto& m : bodies) {
    centres.push_back(m.footprint.pose.position);
    reach = std::max(reach, m.footprint.shape.bound_radius());
  }
  const geometry::PointGrid near(world.workspace.bounds, std::max(2 * reach + 2 * r, 0.1), centres);
  std::vector<int> neighbours;
  std::vector<geometry::Polygon> outlines;
  for (size_t i = 0; i < bodies.size(); ++i) {
    const geometry::Footprint within{bodies[i].footprint.pose, geometry::grown(bodies[i].footprint.shape, 2 * r)};
    const bool in_a_passage = std::any_of(world.fixed_bodies.begin(), world.fixed_bodies.end(),
                                          [&](const auto& f) { return geometry::overlap(within, f.footprint); });
    if (in_a_passage) continue;
    near.near(centres[i], 2 * reach + 2 * r, neighbours);
    const bool in_clutter = std::any_of(neighbours.begin(), neighbours.end(), [&](int j) {
      return j != static_cast<int>(i) && geometry::overlap(within, bodies[static_cast<size_t>(j)].footprint);
    });
    if (!in_clutter) continue;
    for (geometry::Polygon& part : geometry::convex_parts_at(geometry::grown(bodies[i].footprint.shape, r),
                                                             bodies[i].footprint.pose, geometry::CircleAs::kCircumscribed)) {
      outlines.push_back(std::move(part));
    }
  }
  return outlines;
}

// A triangle is a hole where its centroid lies in a fixed body as the mesh's constraints outline it (a
// cylinder as the polygon round it).
bool in_fixed_body(const scenario::FixedBody& body, const Vec2& p) {
  return geometry::contains_as_parts(body.footprint.shape, body.footprint.pose, p, geometry::CircleAs::kCircumscribed);
}

}  // namespace

namespace {

// Steiner points on a staggered grid bound the triangle size away from the constraints. (CGAL's Delaunay
// mesher would be the textbook tool, but it does not terminate on walls that touch the workspace border in
// Debian's CGAL 5.5; the grid gives the same kind of mesh, deterministically.)
void insert_steiner_points(Cdt& cdt, const scenario::World& world, double max_edge) {
  const auto& bounds = world.workspace.bounds;
  const int columns = static_cast<int>(std::ceil(bounds.size().x() / max_edge));
  const int rows = static_cast<int>(std::ceil(bounds.size().y() / max_edge));
  const Vec2 step(bounds.size().x() / columns, bounds.size().y() / rows);
  std::vector<Point> steiner;
  for (int r = 0; r <= rows; ++r) {
    for (int c = 0; c <= columns; ++c) {
      const double shift = (r % 2) * 0.5;
      const Vec2 p = bounds.min + Vec2((c + shift) * step.x(), r * step.y());
      if (!bounds.contains(p)) continue;
      // Points hugging a wall would only make slivers against the wall's own subdivision points.
      const bool near_fixed = std::any_of(world.fixed_bodies.begin(), world.fixed_bodies.end(), [&](const auto& f) {
        return geometry::distance(f.footprint.shape, f.footprint.pose, p) < 0.3 * max_edge;
      });
      if (!near_fixed) steiner.push_back(point(p));
    }
  }
  cdt.insert(steiner.begin(), steiner.end());
}

// The workspace's border, the fixed bodies, the regions and the clutter's outlines as constraints.
Cdt constrained_triangulation(const scenario::World& world, double max_edge) {
  Cdt cdt;
  insert_polygon(cdt, geometry::Polygon::from_rect(world.workspace.bounds).vertices, max_edge);
  for (const auto& f : world.fixed_bodies) {
    for (const auto& part : geometry::convex_parts_at(f.footprint.shape, f.footprint.pose, geometry::CircleAs::kCircumscribed)) {
      insert_polygon(cdt, part.vertices, max_edge);
    }
  }
  for (const auto& r : world.regions) insert_polygon(cdt, r.polygon.vertices, max_edge);
  for (const geometry::Polygon& grown : clutter_outlines(world)) insert_polygon(cdt, grown.vertices, max_edge);
  insert_steiner_points(cdt, world, max_edge);
  return cdt;
}

}  // namespace

Decomposition Decomposition::build(const scenario::World& world, const DecompositionOptions& options) {
  const auto& bounds = world.workspace.bounds;
  const double max_edge = options.max_edge > 0 ? options.max_edge : bounds.size().norm() / 20.0;
  const Cdt cdt = constrained_triangulation(world, max_edge);

  Decomposition d;
  std::map<Cdt::Face_handle, int> index_of;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    Triangle t;
    for (int i = 0; i < 3; ++i) t.corners[i] = vec(f->vertex(i)->point());
    t.centroid = (t.corners[0] + t.corners[1] + t.corners[2]) / 3.0;
    // Fixed-body edges are constraints, so a triangle is wholly inside a body or wholly outside.
    if (std::any_of(world.fixed_bodies.begin(), world.fixed_bodies.end(),
                    [&](const scenario::FixedBody& b) { return in_fixed_body(b, t.centroid); })) {
      continue;
    }
    t.area = 0.5 * std::abs(cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]));
    for (size_t r = 0; r < world.regions.size(); ++r) {
      if (world.regions[r].polygon.contains(t.centroid)) t.region = static_cast<int>(r);
    }
    index_of[f] = static_cast<int>(d.triangles_.size());
    d.triangles_.push_back(std::move(t));
  }
  for (const auto& [face, index] : index_of) {
    for (int i = 0; i < 3; ++i) {
      auto it = index_of.find(face->neighbor(i));
      if (it != index_of.end()) d.triangles_[index].neighbors.push_back(it->second);
    }
    std::sort(d.triangles_[index].neighbors.begin(), d.triangles_[index].neighbors.end());
  }
  d.bucket_triangles(bounds, max_edge);
  return d;
}

void Decomposition::bucket_triangles(const geometry::Rect& bounds, double cell) {
  grid_ = geometry::UniformGrid::covering(bounds, cell);
  buckets_.assign(grid_.size(), {});
  for (int i = 0; i < size(); ++i) {
    Vec2 lo = triangles_[i].corners[0], hi = lo;
    for (const auto& c : triangles_[i].corners) {
      lo = lo.cwiseMin(c);
      hi = hi.cwiseMax(c);
    }
    for (int r = grid_.row(lo.y()); r <= grid_.row(hi.y()); ++r) {
      for (int c = grid_.column(lo.x()); c <= grid_.column(hi.x()); ++c) buckets_[grid_.index(c, r)].push_back(i);
    }
  }
}

int Decomposition::locate(const Vec2& p) const {
  for (int i : buckets_[grid_.index_of(p)]) {
    if (triangle_contains(triangles_[i], p)) return i;
  }
  int nearest = -1;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < size(); ++i) {
    const double d = (triangles_[i].centroid - p).squaredNorm();
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  return nearest;
}

}  // namespace physltl::decomposition
