#pragma once
// Abstract knowledge K of the paper: what stays true while planning. Body classes and properties, the
// robot's capabilities, manipulation-region (mRegion) templates and the propositional regions.
// formulate() is the paper's OntologyFormulation, from the World instead of an OWL file.

#include "physltl/geometry/rect_grid.h"
#include "physltl/geometry/shapes.h"
#include "physltl/geometry/shape.h"
#include "physltl/knowledge/face_set.h"
#include "physltl/scenario/world.h"

#include <string>
#include <vector>

namespace physltl::knowledge {

enum class BodyClass { kFixed, kFreelyMovable, kConstraintOriented };
const char* class_name(BodyClass body_class);  // "fixed", "freely-movable", "constraint-oriented"

struct RobotCapabilities {
  scenario::Drive drive = scenario::Drive::kHolonomic;
  double radius = 0.0;
  double mass = 0.0;
  double max_force = 0.0;      // N, the drive's bound (docs/physics.md)
  double max_speed = 0.0;      // m/s, at every physics step
  double max_turn_rate = 0.0;  // rad/s, differential drive only
  // N the drive can put on a body it pushes: all of max_force, since the robot rolls on its wheels and
  // spends nothing on floor friction of its own.
  double push_force = 0.0;
  geometry::Vec2 start = geometry::Vec2::Zero();
};

// One face the robot may push from (scenario::face_count). Every shape is in the body's frame (body centre
// at the origin).
struct MRegionTemplate {
  int face = 0;
  // The mRegion: a strip along the whole face, as deep as the robot's footprint while it pushes (for a
  // cylinder's sector, the strip that covers that sector's arc). The robot's centre must be inside it for
  // a contact with a constraint-oriented body to count as a push.
  geometry::OrientedBox strip;
  // Where the robot's centre is when it touches the face: the segment at one robot radius from it, as long
  // as the face (a sector: the chord of its arc). The mRegion is active while some stretch of it is free
  // for the robot.
  geometry::Vec2 contact_from = geometry::Vec2::Zero();
  geometry::Vec2 contact_to = geometry::Vec2::Zero();
  // Which way the body goes when pushed from here: into the face, along its inward normal (a sector: at
  // the axis, through the middle of its arc), of unit length.
  geometry::Vec2 push = geometry::Vec2::Zero();
};

struct FixedBodyKnowledge {
  std::string name;
  geometry::Footprint footprint;
  geometry::Rect bounds;  // axis-aligned bounds of the footprint, for cheap rejection tests (walls are long)
};

struct MovableBodyKnowledge {
  std::string name;
  // kFixed when the robot cannot overcome the body's floor friction: it is then an obstacle like a wall.
  BodyClass body_class = BodyClass::kFreelyMovable;
  std::string class_reason;
  geometry::Footprint footprint;  // where the world puts it; stays there when it is too heavy to push
  double bound_radius = 0.0;  // of the footprint about its centre, for cheap rejection tests
  int faces = 0;              // scenario::face_count of its shape
  double mass = 0.0;
  double friction = 0.0;            // the body's own coefficient
  double floor_friction_force = 0.0;  // N needed to start it sliding
  std::vector<MRegionTemplate> mregions;  // the pushable faces; empty for class kFixed
  // The faces the robot can touch (all but those inside a notch narrower than it): all of them active, the
  // body is free.
  FaceSet touchable_faces;
  // The world's rule, not knowledge: the faces the author listed in push_from, as mRegions, whatever the
  // body's class (empty when it lists none: every face). Every planner keeps it (check_validity, both
  // modes); which of them kappa switches off, and the classes, are knowledge.
  std::vector<MRegionTemplate> authored_sides;
  // How far from the body's centre the robot's centre can be while it touches a pushable face.
  double contact_reach = 0.0;
};

struct Proposition {
  std::string name;
  geometry::Polygon region;
};

struct AbstractKnowledge {
  geometry::Rect workspace;
  RobotCapabilities robot;
  std::vector<FixedBodyKnowledge> fixed_bodies;      // World::fixed_bodies order
  // The fixed bodies' bounds, near() the midpoint of any mRegion's contact segment when the robot on that
  // segment could touch them.
  geometry::RectGrid fixed_near;
  std::vector<MovableBodyKnowledge> movable_bodies;  // World::movable_bodies order
  double largest_bound_radius = 0.0;  // of the movable bodies' footprints
  double largest_contact_reach = 0.0;  // of the movable bodies' contact_reach
  std::vector<Proposition> propositions;             // World::regions order
};

struct FormulationSettings {
  double gravity = 9.81;          // m/s^2, as the physics module uses
  double mregion_margin = 0.05;   // m added to the robot's diameter for the default mRegion depth
};

// Coulomb friction coefficient of two touching materials; the physics module combines them the same way.
double combined_friction(double a, double b);

AbstractKnowledge formulate(const scenario::World& world, const FormulationSettings& settings = {});

}  // namespace physltl::knowledge
