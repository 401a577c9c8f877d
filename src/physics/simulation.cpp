#include "physltl/physics/simulation.h"

#include "drive.h"
#include "ode_runtime.h"
#include "shape_geoms.h"
#include "physltl/geometry/point_grid.h"
#include "physltl/geometry/rect_grid.h"

#include <ode/ode.h>
#include <ode/threading_impl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace physltl::physics {
namespace {

constexpr double kGravity = 9.81;           // m/s^2, for floor friction only: motion is planar
constexpr int kMaxContactsPerPair = 4;
constexpr std::size_t kValuesPerBody = PhysicsState::kValuesPerBody;
constexpr std::size_t kBodiesPerBlock = PhysicsState::kBodiesPerBlock;
constexpr std::size_t kBlocksPerChunk = PhysicsState::kBlocksPerChunk;
// ODE pushes overlapping bodies apart at up to this speed. The robot's speed limit holds at every step
// only if this correction stays well below it (docs/physics.md measures what remains).
constexpr double kMaxCorrectingSpeed = 0.1;  // m/s
// The robot's geom is larger than the robot by its speculative margin, so that the contacts where a step
// begins include every body it may reach within the step: this much more than its top speed covers in a
// step, and never under a centimetre (docs/physics.md, "No body sinks into another").
constexpr double kMarginOverReach = 1.2;
constexpr double kMinMargin = 0.01;  // m
// A step Dantzig's LCP fails on is taken again from where it began in 2, then 4 sub-steps; still failing,
// once with ODE's iterative solver (dWorldQuickStep), which never fails. That solver reorders its rows with
// one random generator for the whole process from its 8th iteration on: held to 8 iterations it never
// draws from it, so its steps do not depend on the threads (a plan found with the generator reseeded
// before every such step is byte for byte the same; at 20 iterations it is not).
constexpr int kMostSubSteps = 4;
constexpr int kIterativeSolverIterations = 8;
enum class Solver { kDantzig, kIterative };
// The world's rows are a little soft (dWorldSetCFM) so that Dantzig's LCP solves the contacts; the floor's
// friction and a differential robot's wheel grip stay as stiff as ever, so that they hold what they hold.
constexpr double kFrictionMotorCfm = 1e-6;
// A holonomic robot keeps its heading: the plane-2D joint's angular motor holds it with this torque bound.
constexpr double kHeadingHoldTorque = 1e3;  // N m
// A box slower than scenario::kRestSpeed is at rest: floor friction takes ~0.2 m/s off a sliding box per
// step, so a box this slow would stop within the step anyway, and calling it stopped lets the step skip it.
using scenario::kRestSpeed;

// Coulomb friction of two materials, as Box2D and most engines combine it.
double mix_friction(double a, double b) { return std::sqrt(a * b); }

struct Geom {
  dGeomID id = nullptr;
  // A dynamic body's convex parts, each about `offset` in the body's frame (one at its centre for a box, a
  // cylinder, the robot and a convex polygon; `id` is the first); empty for a fixed body's part.
  std::vector<PartGeom> parts;
  dBodyID body = nullptr;  // null for fixed bodies, and for dynamic ones ODE does not hold now
  dJointID planar = nullptr;  // a dynamic body's plane-2D joint while ODE holds the body
  scenario::RobotContact::Body kind = scenario::RobotContact::Body::kFixed;
  int index = 0;           // into the World's list of its kind; -1 for the robot
  double friction = 0.5;
  double bound_radius = 0.0;  // of the footprint, for a cheap test before dCollide
  // How much larger than the body its geoms are, all round: a moving body's speculative margin (contacts
  // before it sinks in), 0 for fixed bodies. Contacts of inflated geoms are measured on the parts
  // themselves (true_depth).
  double inflation = 0.0;
  scenario::Vec2 position = scenario::Vec2::Zero();  // fixed bodies only: they never move
  // What a dynamic body is made of in ODE, to make it again.
  dMass mass{};
  double floor_force = 0.0;
  double floor_torque = 0.0;
};

// Positions within the sum of two bounding radii: only then can two bodies touch.
bool within_reach(const scenario::Vec2& a, double radius_a, const scenario::Vec2& b, double radius_b) {
  const double reach = radius_a + radius_b;
  return (a - b).squaredNorm() <= reach * reach;
}

}  // namespace

struct Simulation::Impl {
  const scenario::World& world;
  dWorldID ode_world = nullptr;
  dThreadingImplementationID threading = nullptr;
  dJointGroupID contact_group = nullptr;
  std::vector<Geom> dynamic;  // robot first, then movables in World order
  std::vector<Geom> fixed;  // one per convex part of each fixed body
  ConvexStore convex_store;  // the prisms' data, which ODE reads in place
  geometry::RectGrid fixed_near;  // the fixed bodies' bounds, within reach of the largest dynamic body
  // The PhysicsState of the dynamic bodies, kept equal to what ODE holds: every change goes through
  // set_body(). Reading it costs a copy; reading ODE costs calls into bodies spread over memory, and a
  // World with many boxes is read after every step. It also keeps each body's yaw: ODE normalises every
  // quaternion it is given, and normalising is not idempotent in the last bit, so a saved quaternion
  // would not restore exactly; the yaw it was made from does.
  std::vector<double> state;
  // The blocks and chunks of the state last saved or restored, which `state` equals except in the blocks
  // marked changed (listed in changed_blocks, their chunks marked too): saving copies only those, and
  // restoring skips the chunks and blocks it would not change.
  mutable std::vector<std::shared_ptr<const PhysicsState::Block>> blocks;
  mutable std::vector<std::shared_ptr<const PhysicsState::Chunk>> chunks;
  mutable std::vector<char> block_changed, chunk_changed;
  mutable std::vector<int> changed_blocks;
  // Where the dynamic bodies are, kept up to date by set_body(): which of them a body may touch is a lookup
  // among the bodies near it, not a scan of the World.
  geometry::PointGrid dynamic_near;
  double largest_bound_radius = 0.0;  // of the dynamic bodies
  std::vector<char> awake;      // per dynamic body, this step: it is integrated and collided
  std::vector<int> woken;       // this step's awake bodies, ascending after wake_bodies()
  // The boxes ODE holds now, ascending: this step's awake ones. See hold_awake().
  std::vector<int> held_boxes;
  std::vector<char> in_motion;  // per dynamic body: a box with some velocity (the robot is always awake)
  std::vector<int> moving_boxes;   // the boxes in_motion marks, in no particular order
  std::vector<int> candidates;  // scratch for grid lookups
  std::vector<int> movers;      // last step's awake boxes, or the boxes the last restore changed, as World indices
  DriveBody drive;
  DriveEffort last_drive;
  bool last_step_solved = true;
  dJointID wheel_grip = nullptr;  // differential drive only
  dContactGeom contact_buffer[kMaxContactsPerPair];
  std::vector<dContactGeom> pair_contacts;  // collide()'s, kept between calls: no allocation per pair
  // The robot's contacts of the step being taken; a speculative one with the force the solver put on it.
  struct PendingContact {
    scenario::RobotContact contact;
    const dJointFeedback* force = nullptr;  // null: touching where the step began
  };
  std::vector<PendingContact> robot_pending;
  std::deque<dJointFeedback> contact_forces;  // ODE writes into them during the step: addresses must hold
  std::deque<PartOutline> outlines;  // every geom's part, its user data: addresses must hold
  Overlap overlap;  // where the last step ended
  std::vector<Vec2> separating_axes, corners_of_part;  // exact_depth's, kept: no allocation per contact
  // The robot's depth into each body within its margin where the last step ended (below zero, the gap).
  struct RobotEnd {
    scenario::RobotContact::Body body;
    int index = 0;
    double depth = 0.0;
    Vec2 point = Vec2::Zero();
  };
  std::vector<RobotEnd> robot_ends;

  explicit Impl(const scenario::World& w) : world(w) {
    ensure_ode_ready_on_this_thread();
    ode_world = dWorldCreate();
    // ODE's default stepping implementation is one object shared by all worlds; with a planner per
    // thread each world needs its own (Debian's ODE asserts otherwise).
    threading = dThreadingAllocateSelfThreadedImplementation();
    dWorldSetStepThreadingImplementation(ode_world, dThreadingImplementationGetFunctions(threading), threading);
    dWorldSetGravity(ode_world, 0, 0, 0);
    dWorldSetERP(ode_world, 0.2);
    // Every row a little soft: Dantzig's LCP fails on rigid, near-redundant rows (friction rows of a box
    // held by the floor and pushed by the robot into another); at 1e-6 the search of chain_corridor met
    // 60 times more failed steps (docs/physics.md, "Steps the solver fails on").
    dWorldSetCFM(ode_world, 1e-4);
    dWorldSetContactSurfaceLayer(ode_world, 0.001);
    dWorldSetContactMaxCorrectingVel(ode_world, kMaxCorrectingSpeed);
    dWorldSetAutoDisableFlag(ode_world, 0);  // no hidden sleep counters: the state is all in PhysicsState
    dWorldSetQuickStepNumIterations(ode_world, kIterativeSolverIterations);
    contact_group = dJointGroupCreate(0);

    const double floor = w.workspace.floor_friction;
    const auto& r = w.robot;
    dMass mass;
    dMassSetSphereTotal(&mass, r.mass, r.radius);
    // The robot rolls on its wheels: no sliding friction with the floor, only what its drive applies.
    const bool differential = r.drive == scenario::Drive::kDifferential;
    // Boxes move as fast as the robot pushes them: every moving body gets the robot's margin.
    const double margin = std::max(kMinMargin, kMarginOverReach * r.max_speed * w.planner.step_size);
    add_dynamic({{dCreateSphere(nullptr, r.radius + margin), Vec2::Zero(), {{}, r.radius}}}, mass, r.friction,
                r.radius, -1, 0.0, differential ? 0.0 : kHeadingHoldTorque, margin);
    drive = {r.mass, mass.I[2 * 4 + 2], r.radius, r.max_force};
    if (differential) add_wheel_grip(mix_friction(floor, r.friction) * r.mass * kGravity);

    for (size_t i = 0; i < w.movable_bodies.size(); ++i) {
      const auto& b = w.movable_bodies[i];
      const geometry::Shape& shape = b.footprint.shape;
      const double floor_force = mix_friction(floor, b.friction) * b.mass * kGravity;
      // One ODE body, whatever its outline: a geom per convex part, all carried by it. A polygon's parts are
      // ODE convex prisms, whose separating-axis contacts are one point on an axis of ODE's choosing once
      // they overlap: grown by a margin, a polygon flush against a wall would pivot on that point. Its
      // contacts are the robot's margin alone (the depth rule holds it to max_overlap all the same).
      const double body_margin = shape.kind() == geometry::Shape::Kind::kPolygon ? 0.0 : margin;
      add_dynamic(make_geoms(shape, convex_store, body_margin), body_mass(shape, b.mass), b.friction, shape.bound_radius(),
                  static_cast<int>(i), floor_force, floor_torque(shape, floor_force), body_margin);
    }
    std::vector<geometry::Rect> fixed_bounds;
    for (size_t i = 0; i < w.fixed_bodies.size(); ++i) {
      const auto& f = w.fixed_bodies[i];
      for (const PartGeom& part : make_geoms(f.footprint.shape, convex_store)) {
        keep_outline(part);
        Geom g;
        g.id = part.id;
        g.index = static_cast<int>(i);
        g.friction = 0.5;
        g.bound_radius = f.footprint.shape.bound_radius() + part.offset.norm();
        g.position = geometry::to_world(f.footprint.pose, part.offset);
        place(g.id, {g.position, f.footprint.pose.yaw});
        fixed.push_back(g);
        fixed_bounds.push_back(geometry::bounds(f.footprint.shape, f.footprint.pose));
      }
    }
    double reach = 0.0;
    for (const Geom& g : dynamic) reach = std::max(reach, g.bound_radius);
    fixed_near = geometry::RectGrid(fixed_bounds, reach);
    reset();
    largest_bound_radius = reach;
    std::vector<Vec2> positions;
    for (size_t i = 0; i < dynamic.size(); ++i) positions.push_back(position(i));
    dynamic_near = geometry::PointGrid(w.workspace.bounds, 2.0 * reach, positions);
  }

  ~Impl() {
    for (auto& g : dynamic) {
      for (const PartGeom& part : g.parts) dGeomDestroy(part.id);
    }
    for (auto& g : fixed) dGeomDestroy(g.id);
    dJointGroupDestroy(contact_group);
    dWorldDestroy(ode_world);  // also destroys bodies and joints
    dThreadingFreeImplementation(threading);
  }

  // The part's own outline, which the contacts of its (inflated) geom are measured against (true_depth).
  void keep_outline(const PartGeom& part) {
    dGeomSetData(part.id, &outlines.emplace_back(part.outline));
  }

  // How deep the two parts of a contact overlap themselves, not their inflated geoms: the overlap of their
  // outlines' projections on the contact's normal (negative: the gap along it). Exact where the normal is
  // the one between the parts' nearest features, as ODE finds it for a sphere against anything and for
  // faces against faces.
  static double true_depth(const dContactGeom& contact) {
    const Vec2 normal = Vec2(contact.normal[0], contact.normal[1]).normalized();
    const auto [a_low, a_high] = projection(contact.g1, normal);
    const auto [b_low, b_high] = projection(contact.g2, normal);
    return std::min(a_high, b_high) - std::max(a_low, b_low);
  }

  // How deep two parts overlap in the plane, exactly: the least overlap of their outlines' projections on
  // the axes that may separate them, each side's normal of either part and, for a circle, the line from
  // its centre to the other part's nearest corner (or centre). ODE's contact normal between boxes or prisms
  // is not always the least one; this is what the overlap rule judges (docs/physics.md).
  double exact_depth(dGeomID a, dGeomID b) {
    separating_axes.clear();
    add_separating_axes(a, b);
    add_separating_axes(b, a);
    double depth = std::numeric_limits<double>::infinity();
    for (const Vec2& axis : separating_axes) {
      const auto [a_low, a_high] = projection(a, axis);
      const auto [b_low, b_high] = projection(b, axis);
      depth = std::min(depth, std::min(a_high, b_high) - std::max(a_low, b_low));
    }
    return depth;
  }

  void add_separating_axes(dGeomID part, dGeomID other) {
    world_corners(part, corners_of_part);
    if (!corners_of_part.empty()) {
      for (size_t i = 0; i < corners_of_part.size(); ++i) {
        const Vec2 side = corners_of_part[(i + 1) % corners_of_part.size()] - corners_of_part[i];
        separating_axes.push_back(Vec2(-side.y(), side.x()).normalized());
      }
      return;
    }
    const dReal* p = dGeomGetPosition(part);
    const Vec2 centre(p[0], p[1]);
    world_corners(other, corners_of_part);
    if (corners_of_part.empty()) {
      const dReal* q = dGeomGetPosition(other);
      corners_of_part.push_back(Vec2(q[0], q[1]));
    }
    const Vec2 nearest = *std::min_element(corners_of_part.begin(), corners_of_part.end(), [&](const Vec2& x, const Vec2& y) {
      return (x - centre).squaredNorm() < (y - centre).squaredNorm();
    });
    if ((nearest - centre).squaredNorm() > 0.0) separating_axes.push_back((nearest - centre).normalized());
  }

  // A corner `c` of a part's outline where its geom stands at position `p` with rotation `r` (3 x 4, row by row).
  static Vec2 placed(const dReal* p, const dReal* r, const Vec2& c) {
    return {p[0] + r[0] * c.x() + r[1] * c.y(), p[1] + r[4] * c.x() + r[5] * c.y()};
  }

  // The corners of a part's own outline where its geom stands (none for a circle).
  static void world_corners(dGeomID part, std::vector<Vec2>& corners) {
    corners.clear();
    const auto* outline = static_cast<const PartOutline*>(dGeomGetData(part));
    const dReal* p = dGeomGetPosition(part);
    const dReal* r = dGeomGetRotation(part);
    for (const Vec2& c : outline->corners) corners.push_back(placed(p, r, c));
  }

  static std::pair<double, double> projection(dGeomID part, const Vec2& direction) {
    const auto* outline = static_cast<const PartOutline*>(dGeomGetData(part));
    const dReal* p = dGeomGetPosition(part);
    const dReal* r = dGeomGetRotation(part);
    if (outline->corners.empty()) {
      const double centre = p[0] * direction.x() + p[1] * direction.y();
      return {centre - outline->radius, centre + outline->radius};
    }
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const Vec2& c : outline->corners) {
      const Vec2 corner = placed(p, r, c);
      low = std::min(low, corner.dot(direction));
      high = std::max(high, corner.dot(direction));
    }
    return {low, high};
  }

  static void place(dGeomID geom, const geometry::Pose2& pose) {
    dGeomSetPosition(geom, pose.position.x(), pose.position.y(), 0.0);
    dMatrix3 rotation;
    dRFromAxisAndAngle(rotation, 0, 0, 1, pose.yaw);
    dGeomSetRotation(geom, rotation);
  }

  // Boxes start outside ODE (hold_awake() brings them in); the robot is made at once and stays.
  // `bound_radius` of the body itself; its geoms are `inflation` larger.
  void add_dynamic(std::vector<PartGeom> parts, const dMass& mass, double friction, double bound_radius, int index,
                   double floor_force, double floor_torque, double inflation) {
    for (const PartGeom& part : parts) keep_outline(part);
    Geom g;
    g.id = parts.front().id;
    g.parts = std::move(parts);
    g.kind = scenario::RobotContact::Body::kMovable;
    g.index = index;
    g.friction = friction;
    g.bound_radius = bound_radius + inflation;
    g.inflation = inflation;
    g.mass = mass;
    g.floor_force = floor_force;
    g.floor_torque = floor_torque;
    dynamic.push_back(g);
    state.resize(state.size() + kValuesPerBody, 0.0);
    blocks.resize((dynamic.size() + kBodiesPerBlock - 1) / kBodiesPerBlock);
    block_changed.resize(blocks.size(), 0);
    chunks.resize((blocks.size() + kBlocksPerChunk - 1) / kBlocksPerChunk);
    chunk_changed.resize(chunks.size(), 0);
    mark_changed(dynamic.size() - 1);
    awake.push_back(0);
    in_motion.push_back(0);
    if (index < 0) make_body(dynamic.size() - 1);
  }

  // Puts dynamic body i into ODE, in the state `state` holds for it.
  void make_body(size_t i) {
    Geom& g = dynamic[i];
    g.body = dBodyCreate(ode_world);
    dBodySetMass(g.body, &g.mass);
    for (const PartGeom& part : g.parts) {
      dGeomSetBody(part.id, g.body);
      if (g.parts.size() > 1) dGeomSetOffsetPosition(part.id, part.offset.x(), part.offset.y(), 0.0);
    }
    // The plane-2D joint keeps the body on the floor; its motors, driven to zero velocity with a force
    // bound, are the floor's Coulomb friction (static and kinetic) solved together with the contacts.
    g.planar = dJointCreatePlane2D(ode_world, nullptr);
    dJointAttach(g.planar, g.body, nullptr);
    dJointSetPlane2DXParam(g.planar, dParamFMax, g.floor_force);
    dJointSetPlane2DYParam(g.planar, dParamFMax, g.floor_force);
    dJointSetPlane2DAngleParam(g.planar, dParamFMax, g.floor_torque);
    dJointSetPlane2DXParam(g.planar, dParamCFM, kFrictionMotorCfm);
    dJointSetPlane2DYParam(g.planar, dParamCFM, kFrictionMotorCfm);
    dJointSetPlane2DAngleParam(g.planar, dParamCFM, kFrictionMotorCfm);
    write_body(i);
  }

  // Takes dynamic body i out of ODE; `state` keeps it, and its geom stays where the body was.
  void remove_body(size_t i) {
    Geom& g = dynamic[i];
    dJointDestroy(g.planar);
    dBodyDestroy(g.body);  // detaches the geom
    g.planar = nullptr;
    g.body = nullptr;
  }

  // The wheels of a differential robot grip the floor sideways: a velocity constraint across the heading,
  // bounded by Coulomb friction, so the robot slides sideways only when contacts push harder than that.
  // Its axis is set every step, across the heading the step ends in (differential_drive).
  void add_wheel_grip(double max_grip_force) {
    wheel_grip = dJointCreateLMotor(ode_world, nullptr);
    dJointAttach(wheel_grip, dynamic[0].body, nullptr);
    dJointSetLMotorNumAxes(wheel_grip, 1);
    dJointSetLMotorParam(wheel_grip, dParamVel, 0.0);
    dJointSetLMotorParam(wheel_grip, dParamFMax, max_grip_force);
    dJointSetLMotorParam(wheel_grip, dParamCFM, kFrictionMotorCfm);
  }

  double* values(size_t i) { return state.data() + i * kValuesPerBody; }
  const double* values(size_t i) const { return state.data() + i * kValuesPerBody; }
  scenario::Vec2 position(size_t i) const { return {values(i)[0], values(i)[1]}; }

  // Brings body i in ODE to the values `state` holds for it.
  void write_body(size_t i) {
    const dBodyID body = dynamic[i].body;
    const double* v = values(i);
    dBodySetPosition(body, v[0], v[1], v[2]);
    const dQuaternion q = {std::cos(v[3] / 2), 0, 0, std::sin(v[3] / 2)};
    dBodySetQuaternion(body, q);
    dBodySetLinearVel(body, v[4], v[5], v[6]);
    dBodySetAngularVel(body, v[7], v[8], v[9]);
  }

  void mark_changed(size_t body) {
    const size_t b = body / kBodiesPerBlock;
    if (block_changed[b]) return;
    block_changed[b] = 1;
    chunk_changed[b / kBlocksPerChunk] = 1;
    changed_blocks.push_back(static_cast<int>(b));
  }

  // A body ODE does not hold: its geoms where `state` has it, so that what a step measures against it is
  // where it is, not where ODE last held it.
  void place_parts(size_t i) {
    const double* v = values(i);
    const geometry::Pose2 pose{{v[0], v[1]}, v[3]};
    for (const PartGeom& part : dynamic[i].parts) place(part.id, {geometry::to_world(pose, part.offset), pose.yaw});
  }

  // Sets body i in `state`, and in ODE if it holds it (its geoms otherwise), to `v`, in PhysicsState's
  // layout.
  void set_body(size_t i, const double* v) {
    std::copy(v, v + kValuesPerBody, values(i));
    mark_changed(i);
    if (dynamic[i].body != nullptr) {
      write_body(i);
    } else {
      place_parts(i);
    }
    if (dynamic_near.size() == dynamic.size()) dynamic_near.move(static_cast<int>(i), {v[0], v[1]});
    const char moving = i > 0 && !at_rest(i);
    if (moving == in_motion[i]) return;
    in_motion[i] = moving;
    if (moving) {
      moving_boxes.push_back(static_cast<int>(i));
    } else {
      moving_boxes.erase(std::find(moving_boxes.begin(), moving_boxes.end(), static_cast<int>(i)));
    }
  }

  void set_pose(size_t i, const geometry::Pose2& pose) {
    const double v[kValuesPerBody] = {pose.position.x(), pose.position.y(), 0.0, pose.yaw, 0, 0, 0, 0, 0, 0};
    set_body(i, v);
  }

  void reset() {
    set_pose(0, {world.robot.start, world.robot.start_yaw});
    for (size_t i = 0; i < world.movable_bodies.size(); ++i) set_pose(i + 1, world.movable_bodies[i].footprint.pose);
  }

  void save(PhysicsState& out) const {
    for (int changed : changed_blocks) {
      const auto b = static_cast<size_t>(changed);
      blocks[b] = PhysicsState::block_of(state, b);
      block_changed[b] = 0;
    }
    for (int changed : changed_blocks) {
      const size_t c = static_cast<size_t>(changed) / kBlocksPerChunk;
      if (!chunk_changed[c]) continue;
      chunks[c] = PhysicsState::chunk_of(blocks, c);
      chunk_changed[c] = 0;
    }
    changed_blocks.clear();
    out.bodies_ = dynamic.size();
    out.chunks_ = chunks;
  }

  // Bodies whose values already match bit for bit (-0.0 is not 0.0 here) are left alone: a restore usually
  // differs from the current state in the robot and a box or two.
  void restore(const PhysicsState& s) {
    movers.clear();
    for (size_t c = 0; c < chunks.size(); ++c) {
      if (s.chunks_[c] == chunks[c] && !chunk_changed[c]) continue;
      const size_t last_block = std::min(blocks.size(), (c + 1) * kBlocksPerChunk);
      for (size_t b = c * kBlocksPerChunk; b < last_block; ++b) restore_block(s.block(b), b);
      chunks[c] = s.chunks_[c];
      chunk_changed[c] = 0;
    }
    changed_blocks.clear();  // every changed block's chunk was restored
  }

  void restore_block(const std::shared_ptr<const PhysicsState::Block>& block, size_t b) {
    if (block == blocks[b] && !block_changed[b]) return;
    const double* v = block->values.data();
    const size_t end = std::min(dynamic.size(), (b + 1) * kBodiesPerBlock);
    for (size_t i = b * kBodiesPerBlock; i < end; ++i, v += kValuesPerBody) {
      if (std::memcmp(v, values(i), kValuesPerBody * sizeof(double)) == 0) continue;
      set_body(i, v);
      if (i > 0) movers.push_back(static_cast<int>(i) - 1);
    }
    blocks[b] = block;
    block_changed[b] = 0;
  }

  // Whether moving body `mover` may reach resting body `rest` within a step: the mover's margin covers
  // how far it goes in a step, the resting body stays where it is (its own outline, not its margin).
  bool may_touch(size_t mover, size_t rest) const {
    const double rest_radius = dynamic[rest].bound_radius - dynamic[rest].inflation;
    return within_reach(position(mover), dynamic[mover].bound_radius, position(rest), rest_radius);
  }

  bool at_rest(size_t i) const {
    const double* v = values(i);
    return v[4] == 0.0 && v[5] == 0.0 && v[9] == 0.0;
  }

  // Which bodies this step moves: the robot, every box in motion, and every box that may touch one of
  // those, found from each woken body in turn. The others are left out of the step: ODE's solver and the
  // contact tests then cost in proportion to the bodies in motion, not to all bodies in the World. This
  // is a physical simplification, like any engine's sleeping bodies: a box at rest is no longer settled
  // or pushed out of a wall it slightly overlaps. The choice depends only on the state, so restoring a
  // state restores it too.
  void wake_bodies() {
    for (int i : woken) awake[static_cast<size_t>(i)] = 0;
    woken.assign(1, 0);
    awake[0] = 1;
    for (int i : moving_boxes) awake[static_cast<size_t>(i)] = 1, woken.push_back(i);
    for (size_t next = 0; next < woken.size(); ++next) {
      const auto mover = static_cast<size_t>(woken[next]);
      dynamic_near.near(position(mover), dynamic[mover].bound_radius + largest_bound_radius, candidates);
      for (int j : candidates) {
        const auto box = static_cast<size_t>(j);
        if (!awake[box] && may_touch(mover, box)) awake[box] = 1, woken.push_back(j);
      }
    }
    std::sort(woken.begin(), woken.end());
    movers.clear();
    for (int i : woken) {
      if (i > 0) movers.push_back(i - 1);
    }
    hold_awake();
  }

  // ODE holds the awake bodies and no others: its step walks every body and joint it holds, and a World of
  // hundreds of sleeping boxes would cost that walk at every step. The result must not depend on which
  // bodies ODE held before: ODE builds each island from the first of its bodies in its list of bodies,
  // where a new body goes first, so the bodies it holds are kept in the order of making them, ascending by
  // index, as if all had been made at the start. A box that joins below the highest one held has those
  // above it made again after it; a body made again from `state` is the body it was, since every step
  // ends by setting each awake body from `state` (settle()).
  void hold_awake() {
    std::erase_if(held_boxes, [&](int i) {
      if (awake[static_cast<size_t>(i)]) return false;
      remove_body(static_cast<size_t>(i));
      return true;
    });
    size_t keep = 0;  // held boxes below the first box that joins: they stay as they are
    size_t next = 1;  // woken[0] is the robot
    while (keep < held_boxes.size() && held_boxes[keep] == woken[next]) ++keep, ++next;
    for (size_t k = keep; k < held_boxes.size(); ++k) remove_body(static_cast<size_t>(held_boxes[k]));
    held_boxes.resize(keep);
    for (; next < woken.size(); ++next) {
      make_body(static_cast<size_t>(woken[next]));
      held_boxes.push_back(woken[next]);
    }
  }

  // Every convex part of `a` against every part of `b`, in their order, the contacts of all of them kept
  // once each (two parts sharing a corner both find it), each a contact joint of the step. A contact of an
  // inflated geom (the robot's) that is not yet touching is speculative: it lets the bodies close the gap
  // within the step and no further (docs/physics.md, "No body sinks into another"). The robot's contacts
  // wait for the step to say whether they touched (robot_contacts_of_step).
  void collide(const Geom& a, const Geom& b, double dt) {
    gather_pair_contacts(a, b);
    const double inflation = a.inflation + b.inflation;
    for (const dContactGeom& found : pair_contacts) {
      dContact contact{};
      contact.geom = found;
      // One friction row, horizontal: the second tangent is vertical, where the plane-2D joint already
      // holds the bodies, and a duplicate row makes the LCP singular.
      const dReal* normal = contact.geom.normal;
      contact.fdir1[0] = -normal[1];
      contact.fdir1[1] = normal[0];
      contact.fdir1[2] = 0.0;
      contact.surface.mode = dContactApprox1 | dContactFDir1 | dContactMu2 | dContactSoftCFM | dContactSoftERP;
      contact.surface.mu = mix_friction(a.friction, b.friction);
      contact.surface.mu2 = 0.0;
      contact.surface.soft_cfm = 1e-5;
      contact.surface.soft_erp = 0.2;
      const double depth = inflation > 0.0 ? true_depth(found) : found.depth;  // below zero, the gap
      contact.geom.depth = depth;
      if (depth < 0.0) {
        // ODE asks the bodies to part at erp/dt x the depth beyond its surface layer (none here) plus
        // motionN: a negative motionN lets them approach by at most the gap within the step.
        contact.surface.mode |= dContactMotionN;
        contact.surface.motionN = depth / dt;
      }
      dJointID joint = dJointCreateContact(ode_world, contact_group, &contact);
      dJointAttach(joint, a.body, b.body);
      if (a.index >= 0) continue;  // `a` is the robot: it is always the first of a pair
      dJointFeedback* feedback = &contact_forces.emplace_back();
      dJointSetFeedback(joint, feedback);
      robot_pending.push_back({{b.kind, b.index, {found.pos[0], found.pos[1]}}, feedback});
    }
  }

  // The contacts of every convex part of `a` with every part of `b` where they stand, into pair_contacts.
  void gather_pair_contacts(const Geom& a, const Geom& b) {
    pair_contacts.clear();
    const bool inflated = a.inflation + b.inflation > 0.0;
    for_each_part(a, [&](dGeomID part_a) { for_each_part(b, [&](dGeomID part_b) { gather_contacts(part_a, part_b, inflated); }); });
  }

  // The robot's contacts of the step just taken, one per body, where it first touched it: those that
  // touched where the step began, and the speculative ones the solver pressed on.
  // A speculative one counts only where the step ends with the robot at the body (within kTouchingGap): a
  // failed solve can leave force on a row whose bodies stayed apart. Then, as contacts of the step too,
  // the fixed bodies the robot overlaps where the step ends: a step that ends inside a wall touched it.
  void robot_contacts_of_step(std::vector<scenario::RobotContact>& robot_contacts) const {
    robot_contacts.clear();
    const auto known = [&](scenario::RobotContact::Body body, int index) {
      return std::any_of(robot_contacts.begin(), robot_contacts.end(),
                         [&](const scenario::RobotContact& r) { return r.body == body && r.index == index; });
    };
    for (const PendingContact& pending : robot_pending) {
      const scenario::RobotContact& c = pending.contact;
      const bool pressed = pending.force->f1[0] != 0.0 || pending.force->f1[1] != 0.0;
      if (!pressed || robot_end_depth(c.body, c.index) < -kTouchingGap) continue;
      if (!known(c.body, c.index)) robot_contacts.push_back(c);
    }
    for (const RobotEnd& end : robot_ends) {
      if (end.depth > 0.0 && end.body == scenario::RobotContact::Body::kFixed && !known(end.body, end.index)) {
        robot_contacts.push_back({end.body, end.index, end.point});
      }
    }
  }

  double robot_end_depth(scenario::RobotContact::Body body, int index) const {
    for (const RobotEnd& end : robot_ends) {
      if (end.body == body && end.index == index) return end.depth;
    }
    return -std::numeric_limits<double>::infinity();
  }

  // Calls f(a, b) for every pair of bodies within reach of each other with an awake one among them: each
  // awake body with the dynamic bodies above it and the fixed bodies, in a fixed order (no collision
  // space, so contact order never depends on history). Where a step begins, a sleeping body is out of
  // reach of every awake one (wake_bodies woke those); where it ends, an awake one may have come within
  // reach of one, and is measured against it where `state` has it (place_parts). The grid only leaves out
  // fixed bodies too far away to touch, in index order.
  template <class F>
  void for_each_awake_pair(F&& f) {
    for (int awake_index : woken) {
      const auto i = static_cast<size_t>(awake_index);
      const scenario::Vec2 p = position(i);
      const double radius = dynamic[i].bound_radius;
      dynamic_near.near(p, radius + largest_bound_radius, candidates);
      std::sort(candidates.begin(), candidates.end());  // contacts in index order, as testing every pair
      for (int other : candidates) {
        const auto j = static_cast<size_t>(other);
        if (j > i && within_reach(p, radius, position(j), dynamic[j].bound_radius)) f(dynamic[i], dynamic[j]);
      }
      for (int f_index : fixed_near.near(p)) {
        const Geom& g = fixed[static_cast<size_t>(f_index)];
        if (within_reach(p, radius, g.position, g.bound_radius)) f(dynamic[i], g);
      }
    }
  }

  // A fixed body's geom is one convex part (a fixed body has a Geom per part); a dynamic body's are its parts.
  template <class F>
  static void for_each_part(const Geom& g, F&& f) {
    if (g.parts.empty()) return f(g.id);
    for (const PartGeom& part : g.parts) f(part.id);
  }

  // The contacts of two convex parts, added to pair_contacts unless one there is at the same point.
  void gather_contacts(dGeomID part_a, dGeomID part_b, bool inflated) {
    const int found = dCollide(part_a, part_b, kMaxContactsPerPair, contact_buffer, sizeof(dContactGeom));
    // Tall boxes touch at the top and the bottom of the same vertical edge; in the plane those are one
    // contact, and the duplicate rows make the LCP singular ("LCP internal error"), so keep one.
    // ODE's separating-axis test for convex prisms, at zero depth (bodies that just touch, as a polygon
    // placed flush against a wall), picks any axis: a contact along the wall that holds the body fast.
    // Touching without depth pushes nothing; the next step, with depth, has the true normal.
    const bool convex = dGeomGetClass(part_a) == dConvexClass || dGeomGetClass(part_b) == dConvexClass;
    for (int i = 0; i < found; ++i) {
      if (convex && std::abs(contact_buffer[i].normal[2]) > 0.5) continue;
      if (convex && std::abs(inflated ? true_depth(contact_buffer[i]) : contact_buffer[i].depth) <= 1e-9) continue;
      const dReal* p = contact_buffer[i].pos;
      const bool duplicate = std::any_of(pair_contacts.begin(), pair_contacts.end(), [&](const dContactGeom& q) {
        return std::abs(p[0] - q.pos[0]) < 1e-4 && std::abs(p[1] - q.pos[1]) < 1e-4;
      });
      if (!duplicate) pair_contacts.push_back(contact_buffer[i]);
    }
  }


  // After each step: remove the solver's drift out of the plane, and bring slow boxes to rest.
  void settle(size_t i) {
    const dBodyID body = dynamic[i].body;
    const dReal* q = dBodyGetQuaternion(body);
    const dReal* p = dBodyGetPosition(body);
    const dReal* v = dBodyGetLinearVel(body);
    const dReal* w = dBodyGetAngularVel(body);
    double vx = v[0], vy = v[1], wz = w[2];
    if (i > 0 && std::hypot(vx, vy) < kRestSpeed && std::abs(wz) < kRestSpeed) vx = vy = wz = 0.0;
    const double yaw = std::remainder(2.0 * std::atan2(q[3], q[0]), 2.0 * std::numbers::pi);
    const double settled[kValuesPerBody] = {p[0], p[1], 0.0, yaw, vx, vy, 0.0, 0.0, 0.0, wz};
    set_body(i, settled);
  }

  // The robot's and movable body `box`'s part of an EnvironmentState, from `state`.
  void write_robot(scenario::EnvironmentState& out) const {
    const double* v = values(0);
    out.robot_position = {v[0], v[1]};
    out.robot_velocity = {v[4], v[5]};
    out.robot_yaw = v[3];
    out.robot_turn_rate = v[9];
  }
  void write_box(size_t box, scenario::EnvironmentState& out) const {
    const double* v = values(box + 1);
    out.movable_poses[box] = {{v[0], v[1]}, v[3]};
    out.movable_velocities[box] = {v[4], v[5]};
  }

  // The drive's effort for this step; a differential robot's grip turns with it.
  DriveEffort drive_effort(const Vec2& setpoint) {
    const double* robot = values(0);
    const Vec2 velocity(robot[4], robot[5]);
    const double dt = world.planner.step_size;
    if (wheel_grip == nullptr) return holonomic_drive(drive, setpoint, velocity, dt);
    const DifferentialEffort wheels = differential_drive(drive, setpoint, robot[3], velocity, robot[9], dt);
    dJointSetLMotorAxis(wheel_grip, 0, 0, -wheels.heading.y(), wheels.heading.x(), 0.0);
    return wheels.effort;
  }

  // One step of the drive's effort: Dantzig's LCP (dWorldStep) first; when it stops short ("LCP internal
  // error"), the awake bodies go back to where the step began and the step is taken again in 2, then 4
  // sub-steps, each with the contacts where it begins. Still failing, it is taken once more by the
  // iterative solver: a failed Dantzig solve integrates the drive's force without the contact forces that
  // would hold it, which drives a robot pressing a box against a wall straight through the box (the step
  // stays unsolved, last_step_solved, and the overlap it ends with judges it like any other).
  void step(const Vec2& setpoint, std::vector<scenario::RobotContact>& robot_contacts) {
    wake_bodies();
    last_drive = drive_effort(setpoint);
    last_step_solved = integrate(1);
    for (int sub_steps = 2; !last_step_solved && sub_steps <= kMostSubSteps; sub_steps *= 2) {
      for (int i : woken) write_body(static_cast<size_t>(i));  // `state` still holds where the step began
      last_step_solved = integrate(sub_steps);
    }
    if (!last_step_solved) {
      for (int i : woken) write_body(static_cast<size_t>(i));
      integrate(1, Solver::kIterative);
    }
    for (int i : woken) settle(static_cast<size_t>(i));
    measure_overlaps();
    robot_contacts_of_step(robot_contacts);
  }

  // The step in `sub_steps` equal parts, each with the drive's force and the contacts where it begins;
  // whether ODE's solver solved every part.
  bool integrate(int sub_steps, Solver solver = Solver::kDantzig) {
    robot_pending.clear();
    contact_forces.clear();
    const double dt = world.planner.step_size / sub_steps;
    bool solved = true;
    for (int k = 0; k < sub_steps; ++k) {
      dBodyAddForce(dynamic[0].body, last_drive.force.x(), last_drive.force.y(), 0.0);
      dBodyAddTorque(dynamic[0].body, 0.0, 0.0, last_drive.torque);
      for_each_awake_pair([&](const Geom& a, const Geom& b) { collide(a, b, dt); });
      const unsigned long long messages_before = solver_messages_on_this_thread();
      if (solver == Solver::kIterative) {
        dWorldQuickStep(ode_world, dt);
      } else {
        dWorldStep(ode_world, dt);
      }
      dJointGroupEmpty(contact_group);
      solved = solved && solver_messages_on_this_thread() == messages_before;
    }
    return solved;
  }

  // Where the step ended: the deepest overlap of two bodies (last_overlap), and how deep the robot is into
  // each body within its margin (robot_ends; below zero, the gap).
  void measure_overlaps() {
    overlap = {};
    robot_ends.clear();
    for_each_awake_pair([&](const Geom& a, const Geom& b) {
      gather_pair_contacts(a, b);
      const bool inflated = a.inflation + b.inflation > 0.0;
      const dContactGeom* deepest = nullptr;
      const dContactGeom* measured = nullptr;  // the last contact whose two parts exact_depth measured
      double depth = -std::numeric_limits<double>::infinity(), exact = 0.0;
      for (const dContactGeom& found : pair_contacts) {
        const double d = inflated ? true_depth(found) : found.depth;
        if (d > depth) depth = d, deepest = &found;
        if (d <= 0.0) continue;
        if (!inflated) {
          exact = std::max(exact, d);
        } else if (measured == nullptr || measured->g1 != found.g1 || measured->g2 != found.g2) {
          // A pair of parts' contacts come one after another: their exact depth is measured once.
          exact = std::max(exact, exact_depth(found.g1, found.g2));
          measured = &found;
        }
      }
      if (deepest == nullptr) return;
      if (exact > overlap.depth) overlap = {exact, body_id(a), body_id(b)};
      if (a.index < 0) robot_ends.push_back({b.kind, b.index, depth, {deepest->pos[0], deepest->pos[1]}});
    });
  }

  static BodyId body_id(const Geom& g) {
    if (g.index < 0) return {BodyId::Kind::kRobot, -1};
    return {g.kind == scenario::RobotContact::Body::kFixed ? BodyId::Kind::kFixed : BodyId::Kind::kMovable, g.index};
  }
};

std::string body_name(const scenario::World& world, const BodyId& body) {
  const auto i = static_cast<size_t>(body.index);
  switch (body.kind) {
    case BodyId::Kind::kRobot: return "robot";
    case BodyId::Kind::kMovable: return world.movable_bodies[i].name;
    case BodyId::Kind::kFixed: return world.fixed_bodies[i].name;
  }
  return "?";
}

Simulation::Simulation(const scenario::World& world) : impl_(std::make_unique<Impl>(world)) {}
Simulation::~Simulation() = default;

double Simulation::step_size() const { return impl_->world.planner.step_size; }

PhysicsState Simulation::save() const {
  PhysicsState s;
  save(s);
  return s;
}

void Simulation::save(PhysicsState& s) const { impl_->save(s); }

void Simulation::restore(const PhysicsState& s) {
  if (s.bodies_ != impl_->dynamic.size()) {
    throw std::invalid_argument("Simulation::restore: the state is of a World with other bodies");
  }
  impl_->restore(s);
}

double PhysicsState::value(std::size_t body, std::size_t k) const {
  return block(body / kBodiesPerBlock)->values[(body % kBodiesPerBlock) * kValuesPerBody + k];
}

void PhysicsState::set_value(std::size_t body, std::size_t k, double v) {
  const std::size_t b = body / kBodiesPerBlock;
  auto chunk = std::make_shared<Chunk>(*chunks_[b / kBlocksPerChunk]);
  auto copy = std::make_shared<Block>(*chunk->blocks[b % kBlocksPerChunk]);
  copy->values[(body % kBodiesPerBlock) * kValuesPerBody + k] = v;
  chunk->blocks[b % kBlocksPerChunk] = std::move(copy);
  chunks_[b / kBlocksPerChunk] = std::move(chunk);
}

void PhysicsState::copy_values(std::span<double> out) const {
  for (std::size_t b = 0; b < blocks(); ++b) {
    const std::size_t first = b * kBodiesPerBlock * kValuesPerBody;
    const std::size_t count = std::min(block(b)->values.size(), out.size() - first);
    std::copy_n(block(b)->values.begin(), count, out.begin() + static_cast<std::ptrdiff_t>(first));
  }
}

std::shared_ptr<const PhysicsState::Block> PhysicsState::block_of(std::span<const double> values, std::size_t b) {
  auto block = std::make_shared<Block>();
  const std::size_t first = b * kBodiesPerBlock * kValuesPerBody;
  std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(first), std::min(block->values.size(), values.size() - first),
              block->values.begin());
  return block;
}

std::shared_ptr<const PhysicsState::Chunk> PhysicsState::chunk_of(std::span<const std::shared_ptr<const Block>> blocks, std::size_t c) {
  auto chunk = std::make_shared<Chunk>();
  const std::size_t first = c * kBlocksPerChunk;
  std::copy_n(blocks.begin() + static_cast<std::ptrdiff_t>(first), std::min(kBlocksPerChunk, blocks.size() - first), chunk->blocks.begin());
  return chunk;
}

PhysicsState PhysicsState::from_values(std::span<const double> values) {
  PhysicsState s;
  s.bodies_ = values.size() / kValuesPerBody;
  std::vector<std::shared_ptr<const Block>> blocks;
  for (std::size_t b = 0; b < s.blocks(); ++b) blocks.push_back(block_of(values, b));
  for (std::size_t c = 0; c * kBlocksPerChunk < blocks.size(); ++c) s.chunks_.push_back(chunk_of(blocks, c));
  return s;
}

std::size_t PhysicsState::blocks_shared_with(const PhysicsState& other) const {
  std::size_t shared = 0;
  for (std::size_t b = 0; b < std::min(blocks(), other.blocks()); ++b) shared += block(b) == other.block(b);
  return shared;
}

bool PhysicsState::operator==(const PhysicsState& other) const {
  if (bodies_ != other.bodies_) return false;
  for (std::size_t c = 0; c < chunks_.size(); ++c) {
    if (chunks_[c] == other.chunks_[c]) continue;
    for (std::size_t b = c * kBlocksPerChunk; b < std::min(blocks(), (c + 1) * kBlocksPerChunk); ++b) {
      const Block& x = *block(b);
      const Block& y = *other.block(b);
      if (&x != &y && std::memcmp(x.values.data(), y.values.data(), sizeof(x.values)) != 0) return false;
    }
  }
  return true;
}

void Simulation::step(const Vec2& setpoint, std::vector<scenario::RobotContact>& contacts) {
  impl_->step(setpoint, contacts);
}

const DriveEffort& Simulation::last_drive() const { return impl_->last_drive; }

bool Simulation::last_step_solved() const { return impl_->last_step_solved; }

const Overlap& Simulation::last_overlap() const { return impl_->overlap; }

std::span<const int> Simulation::last_movers() const { return impl_->movers; }

void Simulation::update_environment(scenario::EnvironmentState& out) const {
  impl_->write_robot(out);
  for (int i : impl_->movers) impl_->write_box(static_cast<size_t>(i), out);
}

void Simulation::read_environment(scenario::EnvironmentState& out) const {
  const size_t boxes = impl_->dynamic.size() - 1;
  impl_->write_robot(out);
  out.movable_poses.resize(boxes);
  out.movable_velocities.resize(boxes);
  for (size_t i = 0; i < boxes; ++i) impl_->write_box(i, out);
}

scenario::EnvironmentState Simulation::environment() const {
  scenario::EnvironmentState s;
  read_environment(s);
  return s;
}

}  // namespace physltl::physics
