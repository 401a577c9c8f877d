#include "shape_geoms.h"

#include <array>
#include <cmath>

namespace physltl::physics {
namespace {

using geometry::Vec2;

// Integrals over a convex polygon by its fan of triangles from the first corner, each cut into `n` x `n`
// small triangles evaluated at their centroids: f's integral over the area.
template <class F>
double integrate(const geometry::Polygon& p, F&& f, int n = 16) {
  double total = 0.0;
  const auto& v = p.vertices;
  for (size_t k = 1; k + 1 < v.size(); ++k) {
    const Vec2 a = v[0], u = (v[k] - a) / n, w = (v[k + 1] - a) / n;
    const double small = 0.5 * std::abs(u.x() * w.y() - u.y() * w.x());
    for (int i = 0; i < n; ++i) {
      for (int j = 0; i + j < n; ++j) {
        const Vec2 corner = a + i * u + j * w;
        total += small * f(corner + (u + w) / 3.0);
        if (i + j + 1 < n) total += small * f(corner + 2.0 * (u + w) / 3.0);  // the upside-down one
      }
    }
  }
  return total;
}

}  // namespace

dGeomID ConvexStore::prism(const geometry::Polygon& outline, const Vec2& centre) {
  Prism& p = prisms_.emplace_back();
  std::vector<Vec2> v;
  for (const Vec2& c : outline.vertices) v.push_back(c - centre);
  const auto n = static_cast<unsigned>(v.size());
  const double half = kCollisionHeight / 2;
  for (const Vec2& c : v) p.points.insert(p.points.end(), {c.x(), c.y(), half});
  for (const Vec2& c : v) p.points.insert(p.points.end(), {c.x(), c.y(), -half});
  p.planes.insert(p.planes.end(), {0, 0, 1, half});
  p.faces.push_back(n);
  for (unsigned i = 0; i < n; ++i) p.faces.push_back(i);
  p.planes.insert(p.planes.end(), {0, 0, -1, half});
  p.faces.push_back(n);
  for (unsigned i = n; i-- > 0;) p.faces.push_back(n + i);
  for (unsigned i = 0; i < n; ++i) {
    const unsigned j = (i + 1) % n;
    const Vec2 edge = v[j] - v[i];
    const Vec2 normal = Vec2(edge.y(), -edge.x()).normalized();
    p.planes.insert(p.planes.end(), {normal.x(), normal.y(), 0, normal.dot(v[i])});
    p.faces.insert(p.faces.end(), {4u, i, n + i, n + j, j});
  }
  return dCreateConvex(nullptr, p.planes.data(), n + 2, p.points.data(), 2 * n, p.faces.data());
}

namespace {

// What each kind of shape is to ODE, one row per kind (geometry/shape_kinds.h has the geometry's): its
// geoms, its mass distribution and the floor's friction torque.
struct ShapeKindPhysics {
  std::vector<PartGeom> (*geoms)(const geometry::Shape& shape, ConvexStore& store, double inflation);
  dMass (*mass)(const geometry::Shape& shape, double mass);
  double (*floor_torque)(const geometry::Shape& shape, double floor_force);
};

namespace box {

Vec2 size(const geometry::Shape& shape) { return 2.0 * shape.half_extents(); }

constexpr ShapeKindPhysics kRow{
    [](const geometry::Shape& shape, ConvexStore&, double inflation) {
      const Vec2 inflated = size(shape) + Vec2::Constant(2.0 * inflation);
      const Vec2 h = shape.half_extents();
      return std::vector<PartGeom>{{dCreateBox(nullptr, inflated.x(), inflated.y(), kCollisionHeight), Vec2::Zero(),
                                    {{{-h.x(), -h.y()}, {h.x(), -h.y()}, {h.x(), h.y()}, {-h.x(), h.y()}}, 0.0}}};
    },
    [](const geometry::Shape& shape, double mass) {
      dMass m;
      dMassSetBoxTotal(&m, mass, size(shape).x(), size(shape).y(), kCollisionHeight);
      return m;
    },
    [](const geometry::Shape& shape, double floor_force) { return floor_force * (2.0 / 3.0) * shape.half_extents().mean(); },
};

}  // namespace box

namespace circle {

constexpr ShapeKindPhysics kRow{
    [](const geometry::Shape& shape, ConvexStore&, double inflation) {
      return std::vector<PartGeom>{
          {dCreateCylinder(nullptr, shape.radius() + inflation, kCollisionHeight), Vec2::Zero(), {{}, shape.radius()}}};
    },
    [](const geometry::Shape& shape, double mass) {
      dMass m;
      dMassSetCylinderTotal(&m, mass, 3, shape.radius(), kCollisionHeight);
      return m;
    },
    // Exact for a disc.
    [](const geometry::Shape& shape, double floor_force) { return floor_force * (2.0 / 3.0) * shape.radius(); },
};

}  // namespace circle

namespace polygon {

// The convex, counter-clockwise `part` with each side moved out by `by`: its corners where the moved sides
// meet, so the corners stay square.
geometry::Polygon pushed_out(const geometry::Polygon& part, double by) {
  if (by == 0.0) return part;
  const std::vector<Vec2>& v = part.vertices;
  const size_t n = v.size();
  geometry::Polygon out;
  for (size_t i = 0; i < n; ++i) {
    const Vec2& prev = v[(i + n - 1) % n];
    const Vec2 in = (v[i] - prev).normalized(), next = (v[(i + 1) % n] - v[i]).normalized();
    // Outward normals of a counter-clockwise polygon's sides point right of their direction.
    const Vec2 n_in(in.y(), -in.x()), n_next(next.y(), -next.x());
    out.vertices.push_back(v[i] + by * (n_in + n_next) / (1.0 + n_in.dot(n_next)));
  }
  return out;
}

std::vector<PartGeom> geoms(const geometry::Shape& shape, ConvexStore& store, double inflation) {
  std::vector<PartGeom> geoms;
  // A convex body's one part is about its centroid already, the body's centre; a fixed body's parts each
  // about their own.
  const bool one = shape.parts().size() == 1;
  for (const geometry::Polygon& part : shape.parts()) {
    const Vec2 centre = one ? Vec2::Zero() : part.centroid();
    PartOutline outline;
    for (const Vec2& corner : part.vertices) outline.corners.push_back(corner - centre);
    geoms.push_back({store.prism(pushed_out(part, inflation), centre), centre, std::move(outline)});
  }
  return geoms;
}

// The prism's second moments about its centroid (the body's origin).
dMass mass(const geometry::Shape& shape, double mass) {
  double area = 0.0, xx = 0.0, yy = 0.0, xy = 0.0;
  for (const geometry::Polygon& part : shape.parts()) {
    area += integrate(part, [](const Vec2&) { return 1.0; });
    xx += integrate(part, [](const Vec2& p) { return p.x() * p.x(); });
    yy += integrate(part, [](const Vec2& p) { return p.y() * p.y(); });
    xy += integrate(part, [](const Vec2& p) { return p.x() * p.y(); });
  }
  dMass m;
  const double density = mass / area, z2 = mass * kCollisionHeight * kCollisionHeight / 12.0;
  dMassSetParameters(&m, mass, 0, 0, 0, density * yy + z2, density * xx + z2, density * (xx + yy), -density * xy, 0, 0);
  return m;
}

double floor_torque(const geometry::Shape& shape, double floor_force) {
  double area = 0.0, moment = 0.0;
  for (const geometry::Polygon& part : shape.parts()) {
    area += integrate(part, [](const Vec2&) { return 1.0; });
    moment += integrate(part, [](const Vec2& p) { return p.norm(); });
  }
  return floor_force * moment / area;
}

constexpr ShapeKindPhysics kRow{geoms, mass, floor_torque};

}  // namespace polygon

// geometry::Shape::Kind order.
constexpr std::array<const ShapeKindPhysics*, 3> kKinds = {&box::kRow, &circle::kRow, &polygon::kRow};

const ShapeKindPhysics& kind_of(const geometry::Shape& shape) { return *kKinds[static_cast<std::size_t>(shape.kind())]; }

}  // namespace

std::vector<PartGeom> make_geoms(const geometry::Shape& shape, ConvexStore& store, double inflation) {
  return kind_of(shape).geoms(shape, store, inflation);
}

dMass body_mass(const geometry::Shape& shape, double mass) { return kind_of(shape).mass(shape, mass); }

double floor_torque(const geometry::Shape& shape, double floor_force) { return kind_of(shape).floor_torque(shape, floor_force); }

}  // namespace physltl::physics
