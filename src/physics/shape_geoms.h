#pragma once
// What ODE makes of a footprint: its geoms (a box, an upright cylinder, a convex prism per convex part),
// and for a movable body its mass distribution and the floor's friction torque. Every body spans
// z = +-kCollisionHeight / 2, so contact normals stay horizontal.

#include "physltl/geometry/shape.h"

#include <ode/ode.h>

#include <deque>
#include <vector>

namespace physltl::physics {

inline constexpr double kCollisionHeight = 1.0;  // m

// The planes, points and faces of the convex prisms: ODE keeps pointers to them, not copies.
class ConvexStore {
 public:
  // A prism over the convex, counter-clockwise `outline`, as a geom of no space whose origin is
  // `centre` of the outline's frame (ODE wants its origin inside the prism).
  dGeomID prism(const geometry::Polygon& outline, const geometry::Vec2& centre);

 private:
  struct Prism {
    std::vector<dReal> planes;   // a, b, c, d per face: a x + b y + c z = d
    std::vector<dReal> points;   // x, y, z per corner
    std::vector<unsigned> faces;  // per face: its corner count, then its corners counter-clockwise from outside
  };
  std::deque<Prism> prisms_;
};

// A convex part's own outline in its geom's frame: its corners, or a circle's radius (no corners).
struct PartOutline {
  std::vector<geometry::Vec2> corners;
  double radius = 0.0;
};

// One geom per convex part (a box and a cylinder are one), each about its own origin, which stands at
// `offset` in the body's frame (a box's and a cylinder's at the body's centre). The geom is larger than
// the part by `inflation` all round (a moving body's speculative margin: docs/physics.md, "No body sinks
// into another"); `outline` is the part itself.
struct PartGeom {
  dGeomID id = nullptr;
  geometry::Vec2 offset = geometry::Vec2::Zero();
  PartOutline outline;
};
std::vector<PartGeom> make_geoms(const geometry::Shape& shape, ConvexStore& store, double inflation = 0.0);

// A body of `mass` kg, uniformly dense over its footprint.
dMass body_mass(const geometry::Shape& shape, double mass);

// The floor's resistance to turning a body pressed down with `floor_force` (its sliding friction): the
// friction at the mean distance of its footprint from its centre, as for uniform pressure (a box keeps
// the estimate it always had, two thirds of its mean half extent).
double floor_torque(const geometry::Shape& shape, double floor_force);

}  // namespace physltl::physics
