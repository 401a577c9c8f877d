#include "physltl/knowledge/kappa.h"

#include "obstacle.h"
#include "shape_kinds.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace physltl::knowledge {
namespace {

using geometry::Vec2;

// The robot's centre sliding along one side of a body, at one robot radius from it.
struct ContactSegment {
  Vec2 from;
  Vec2 direction;  // unit
  double length;

  double distance_to(const Vec2& p) const {
    const double t = std::clamp((p - from).dot(direction), 0.0, length);
    return (from + t * direction - p).norm();
  }

  // Whether the robot anywhere on the segment could reach into `box`, judged by bounding rectangles.
  bool may_reach(const geometry::Rect& box, double radius) const {
    const Vec2 to = from + length * direction;
    const Vec2 lo = from.cwiseMin(to) - Vec2::Constant(radius);
    const Vec2 hi = from.cwiseMax(to) + Vec2::Constant(radius);
    return (lo.array() < box.max.array()).all() && (hi.array() > box.min.array()).all();
  }
};

// The stretches of the segment on which the robot would overlap an obstacle: a fixed body or any other
// movable body near the segment.
// Scratch space of the inferences on one thread.
struct Scratch {
  std::vector<size_t> moved;
  std::vector<int> nearby;
  std::vector<int> affected;
  std::vector<geometry::Vec2> before;
  std::vector<Interval> blocked;
};

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

void blocked_stretches(const AbstractKnowledge& k, const scenario::EnvironmentState& state,
                       const BodyLocator& bodies, size_t pushed, const ContactSegment& segment,
                       std::vector<Interval>& blocked) {
  const double r = k.robot.radius;
  auto add = [&](const geometry::Shape& shape, const geometry::Pose2& pose) {
    Obstacle(shape, pose).closer_than(segment.from, segment.direction, r, blocked);
  };
  // Every point of the segment lies within half its length of its middle.
  const Vec2 middle = segment.from + 0.5 * segment.length * segment.direction;
  for (int f : k.fixed_near.near(middle)) {
    const FixedBodyKnowledge& fixed = k.fixed_bodies[static_cast<size_t>(f)];
    if (segment.may_reach(fixed.bounds, r)) add(fixed.footprint.shape, fixed.footprint.pose);
  }
  std::vector<int>& nearby = scratch().nearby;
  bodies.near(middle, 0.5 * segment.length + k.largest_bound_radius + r, nearby);
  for (int body : nearby) {
    const auto j = static_cast<size_t>(body);
    const auto& other = k.movable_bodies[j];
    const geometry::Pose2& pose = state.movable_poses[j];
    const double near = 0.5 * segment.length + other.bound_radius + r;
    if (j == pushed || (pose.position - middle).squaredNorm() >= near * near) continue;
    if (segment.distance_to(pose.position) >= other.bound_radius + r) continue;
    add(other.footprint.shape, pose);
  }
}

// Whether the robot can stand somewhere along the segment: inside the workspace and clear of obstacles.
// `blocked` is scratch space, reused so that the planner's inference after every step does not allocate.
bool has_free_stretch(const AbstractKnowledge& k, const scenario::EnvironmentState& state, const BodyLocator& bodies,
                      size_t pushed, const ContactSegment& segment, std::vector<Interval>& blocked) {
  const Vec2 workspace_center = 0.5 * (k.workspace.min + k.workspace.max);
  const Vec2 room_for_centre = 0.5 * k.workspace.size() - Vec2::Constant(k.robot.radius);
  if (room_for_centre.minCoeff() <= 0.0) return false;
  const Interval in_workspace =
      inside_rectangle(segment.from - workspace_center, segment.direction, room_for_centre);
  const double end = std::min(segment.length, in_workspace.hi);
  blocked.clear();
  blocked_stretches(k, state, bodies, pushed, segment, blocked);
  std::sort(blocked.begin(), blocked.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  // Sweep t forward past every blocked stretch that covers [t, t + kMinFreeStretch). In order of their
  // starts, the first stretch that starts beyond that window leaves it free, and so do all later ones.
  double t = std::max(0.0, in_workspace.lo);
  for (const Interval& b : blocked) {
    if (b.lo >= t + kMinFreeStretch) break;
    t = std::max(t, b.hi);
  }
  return t + kMinFreeStretch <= end;
}

Vec2 to_world(const geometry::Pose2& pose, double cos_yaw, double sin_yaw, const Vec2& local) {
  return pose.position + Vec2(cos_yaw * local.x() - sin_yaw * local.y(), sin_yaw * local.x() + cos_yaw * local.y());
}

BodyType type_of(const MovableBodyKnowledge& body, FaceSet active) {
  if (body.body_class == BodyClass::kFixed || active.empty()) return BodyType::kImmovable;
  return active == body.touchable_faces ? BodyType::kFree : BodyType::kConstraintOriented;
}

BodyKappa infer_body(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state,
                     const BodyLocator& bodies, size_t i, std::vector<Interval>& blocked) {
  const MovableBodyKnowledge& body = knowledge.movable_bodies[i];
  const geometry::Pose2& pose = state.movable_poses[i];
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  FaceSet active;
  for (const MRegionTemplate& m : body.mregions) {
    const Vec2 from = to_world(pose, c, s, m.contact_from);
    const Vec2 along = to_world(pose, c, s, m.contact_to) - from;
    const double length = along.norm();
    if (length > 0.0 && has_free_stretch(knowledge, state, bodies, i, {from, along / length, length}, blocked)) {
      active.insert(m.face);
    }
  }
  return {type_of(body, active), active};
}

void check_body_count(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state) {
  if (state.movable_poses.size() != knowledge.movable_bodies.size()) {
    throw std::invalid_argument("infer: the state has a different number of movable bodies than the knowledge");
  }
}

}  // namespace

const char* type_name(BodyType type) {
  switch (type) {
    case BodyType::kFree: return "free";
    case BodyType::kConstraintOriented: return "constraint-oriented";
    case BodyType::kImmovable: return "immovable";
  }
  return "?";
}

void infer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state, Kappa& kappa) {
  check_body_count(knowledge, state);
  infer(knowledge, state, BodyLocator(knowledge, state.movable_poses), kappa);
}

void infer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state, const BodyLocator& bodies,
           Kappa& kappa) {
  check_body_count(knowledge, state);
  kappa.bodies.resize(knowledge.movable_bodies.size());
  std::vector<Interval>& blocked = scratch().blocked;
  for (size_t i = 0; i < kappa.bodies.size(); ++i) kappa.bodies[i] = infer_body(knowledge, state, bodies, i, blocked);
}

namespace {

// Cells about the size of the largest lookup: a contact segment's half length plus a body and the robot.
double locator_cell(const AbstractKnowledge& knowledge) {
  return std::max(knowledge.largest_contact_reach + knowledge.robot.radius, 0.1);
}

std::vector<geometry::Vec2> centres(std::span<const geometry::Pose2> poses) {
  std::vector<geometry::Vec2> c;
  c.reserve(poses.size());
  for (const auto& p : poses) c.push_back(p.position);
  return c;
}

}  // namespace

BodyLocator::BodyLocator(const AbstractKnowledge& knowledge, std::span<const geometry::Pose2> poses, double cell)
    : poses_(poses.begin(), poses.end()),
      grid_(knowledge.workspace, cell > 0.0 ? cell : locator_cell(knowledge), centres(poses)) {}

void BodyLocator::move(std::size_t body, const geometry::Pose2& pose) {
  poses_[body] = pose;
  grid_.move(static_cast<int>(body), pose.position);
}

namespace {

bool pose_changed(const geometry::Pose2& now, const geometry::Pose2& was) {
  return now.position != was.position || now.yaw != was.yaw;
}

void check_reinfer_sizes(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state,
                         const BodyLocator& inferred_for, const Kappa& kappa) {
  check_body_count(knowledge, state);
  const size_t n = knowledge.movable_bodies.size();
  if (inferred_for.poses().size() != n || kappa.bodies.size() != n) {
    throw std::invalid_argument("reinfer: kappa was inferred for a different number of movable bodies");
  }
}

// reinfer once the bodies whose pose changed are in scratch().moved.
void reinfer_moved(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state,
                   BodyLocator& inferred_for, Kappa& kappa) {
  Scratch& s = scratch();
  if (s.moved.empty()) return;
  // A moved body changes i's mRegions only if it comes, before or after the move, within a robot's
  // diameter of a contact segment of i. The locator then holds the new positions, which are i's centres.
  const double r = knowledge.robot.radius;
  s.affected.clear();
  s.before.clear();
  for (size_t j : s.moved) s.before.push_back(inferred_for.poses()[j].position);
  for (size_t j : s.moved) inferred_for.move(j, state.movable_poses[j]);
  for (size_t m = 0; m < s.moved.size(); ++m) {
    const size_t j = s.moved[m];
    s.affected.push_back(static_cast<int>(j));
    const double widest = knowledge.largest_contact_reach + 2.0 * r + knowledge.movable_bodies[j].bound_radius;
    for (const geometry::Vec2& at : {s.before[m], state.movable_poses[j].position}) {
      inferred_for.near(at, widest, s.nearby);
      for (int candidate : s.nearby) {
        const auto i = static_cast<size_t>(candidate);
        const double reach = knowledge.movable_bodies[i].contact_reach + 2.0 * r + knowledge.movable_bodies[j].bound_radius;
        if ((at - state.movable_poses[i].position).squaredNorm() < reach * reach) s.affected.push_back(candidate);
      }
    }
  }
  std::sort(s.affected.begin(), s.affected.end());
  s.affected.erase(std::unique(s.affected.begin(), s.affected.end()), s.affected.end());
  for (int i : s.affected) {
    kappa.bodies[static_cast<size_t>(i)] = infer_body(knowledge, state, inferred_for, static_cast<size_t>(i), s.blocked);
  }
}

}  // namespace

void reinfer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state, BodyLocator& inferred_for,
             Kappa& kappa) {
  check_reinfer_sizes(knowledge, state, inferred_for, kappa);
  Scratch& s = scratch();
  s.moved.clear();
  for (size_t j = 0; j < knowledge.movable_bodies.size(); ++j) {
    if (pose_changed(state.movable_poses[j], inferred_for.poses()[j])) s.moved.push_back(j);
  }
  reinfer_moved(knowledge, state, inferred_for, kappa);
}

void reinfer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state, BodyLocator& inferred_for,
             Kappa& kappa, std::span<const int> maybe_moved) {
  check_reinfer_sizes(knowledge, state, inferred_for, kappa);
  Scratch& s = scratch();
  s.moved.clear();
  for (int body : maybe_moved) {
    const auto j = static_cast<size_t>(body);
    if (pose_changed(state.movable_poses[j], inferred_for.poses()[j])) s.moved.push_back(j);
  }
  reinfer_moved(knowledge, state, inferred_for, kappa);
}

Kappa infer(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state) {
  Kappa kappa;
  infer(knowledge, state, kappa);
  return kappa;
}

geometry::Vec2 push_direction(const MRegionTemplate& mregion, const geometry::Pose2& body_pose) {
  const geometry::Vec2& n = mregion.push;
  const double c = std::cos(body_pose.yaw), s = std::sin(body_pose.yaw);
  return {c * n.x() - s * n.y(), s * n.x() + c * n.y()};
}

std::vector<geometry::Vec2> allowed_push_directions(const MovableBodyKnowledge& body, const BodyKappa& kappa,
                                                    const geometry::Pose2& pose) {
  std::vector<geometry::Vec2> directions;
  for (const MRegionTemplate& m : body.mregions) {
    if (kappa.active_faces.contains(m.face)) directions.push_back(push_direction(m, pose));
  }
  return directions;
}

geometry::OrientedBox mregion_at(const MRegionTemplate& mregion, const geometry::Pose2& body_pose) {
  const double c = std::cos(body_pose.yaw), s = std::sin(body_pose.yaw);
  geometry::OrientedBox strip = mregion.strip;
  strip.pose.position = to_world(body_pose, c, s, mregion.strip.pose.position);
  strip.pose.yaw = body_pose.yaw + mregion.strip.pose.yaw;
  return strip;
}

}  // namespace physltl::knowledge
