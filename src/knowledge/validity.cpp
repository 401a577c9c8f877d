#include "physltl/knowledge/validity.h"

#include "shape_kinds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace physltl::knowledge {
namespace {

bool robot_inside_workspace(const AbstractKnowledge& k, const geometry::Vec2& centre) {
  const geometry::Vec2 margin = geometry::Vec2::Constant(k.robot.radius - kWorkspaceTolerance);
  return geometry::Rect{k.workspace.min + margin, k.workspace.max - margin}.contains(centre);
}

// The robot's centre, not the contact point, decides the side: the contact point lies on the body's
// outline, where the strips of two sides meet at every corner. A centre up to `slack` beyond the ends of
// an active side's strip still pushes from that side (kPushSideSlack).
bool in_strip(const MRegionTemplate& m, const geometry::Pose2& pose, const geometry::Vec2& robot_centre, double slack) {
  geometry::OrientedBox strip = mregion_at(m, pose);
  strip.half_extents += geometry::Vec2::Constant(slack);
  return strip.contains(robot_centre);
}

bool pushes_from_active_mregion(const MovableBodyKnowledge& body, const BodyKappa& kappa,
                                const geometry::Pose2& pose, const geometry::Vec2& robot_centre, double slack) {
  return std::any_of(body.mregions.begin(), body.mregions.end(), [&](const MRegionTemplate& m) {
    return kappa.active_faces.contains(m.face) && in_strip(m, pose, robot_centre, slack);
  });
}

// The world's rule (push_from), for a planner without knowledge: a face the author did not list is one the
// robot may not push from. With knowledge, the rule on kappa's active mRegions (a subset of these) implies it.
bool pushes_from_authored_side(const MovableBodyKnowledge& body, const geometry::Pose2& pose,
                               const geometry::Vec2& robot_centre, double slack) {
  return body.authored_sides.empty() ||
         std::any_of(body.authored_sides.begin(), body.authored_sides.end(),
                     [&](const MRegionTemplate& m) { return in_strip(m, pose, robot_centre, slack); });
}

}  // namespace

const char* violation_name(Violation violation) {
  switch (violation) {
    case Violation::kNone: return "none";
    case Violation::kExceedsRobotLimits: return "robot exceeds its speed or turn-rate limit";
    case Violation::kLeftWorkspace: return "left the workspace";
    case Violation::kTouchesFixedBody: return "robot touches a fixed body";
    case Violation::kTouchesImmovableBody: return "robot touches an immovable body";
    case Violation::kPushesFromForbiddenSide: return "robot pushes a constraint-oriented body from a forbidden side";
    case Violation::kBodiesOverlap: return "two bodies overlap deeper than max_overlap";
  }
  return "?";
}

namespace {

// check_validity's rules with the workspace test of the movable bodies in `tested` only.
template <typename Bodies>
Validity check(const AbstractKnowledge& knowledge, const Kappa& kappa, const scenario::EnvironmentState& state,
               std::span<const scenario::RobotContact> contacts, ValidityMode mode, const Bodies& tested) {
  const size_t n = knowledge.movable_bodies.size();
  const bool uses_kappa = mode == ValidityMode::kKnowledge;
  if (state.movable_poses.size() != n || (uses_kappa && kappa.bodies.size() != n)) {
    throw std::invalid_argument("check_validity: state, kappa and knowledge disagree on the movable bodies");
  }
  if (!within_robot_limits(knowledge.robot, state)) return {Violation::kExceedsRobotLimits, -1};
  if (!robot_inside_workspace(knowledge, state.robot_position)) return {Violation::kLeftWorkspace, -1};
  for (const auto body : tested) {
    const auto i = static_cast<size_t>(body);
    if (!geometry::inside(knowledge.movable_bodies[i].footprint.shape, state.movable_poses[i], knowledge.workspace,
                          kWorkspaceTolerance)) {
      return {Violation::kLeftWorkspace, static_cast<int>(i)};
    }
  }
  for (const scenario::RobotContact& contact : contacts) {
    if (contact.body == scenario::RobotContact::Body::kFixed) return {Violation::kTouchesFixedBody, contact.index};
    const auto i = static_cast<size_t>(contact.index);
    if (!uses_kappa) {
      if (!pushes_from_authored_side(knowledge.movable_bodies[i], state.movable_poses[i], state.robot_position,
                                     kPushSideSlack)) {
        return {Violation::kPushesFromForbiddenSide, contact.index};
      }
      continue;
    }
    const BodyKappa& body_kappa = kappa.bodies.at(i);
    if (body_kappa.type == BodyType::kImmovable) return {Violation::kTouchesImmovableBody, contact.index};
    if (body_kappa.type == BodyType::kConstraintOriented &&
        !pushes_from_active_mregion(knowledge.movable_bodies[i], body_kappa, state.movable_poses[i],
                                    state.robot_position, kPushSideSlack)) {
      return {Violation::kPushesFromForbiddenSide, contact.index};
    }
  }
  return {};
}

// 0, 1, ..., n - 1 without storing them.
struct AllBodies {
  std::size_t n;
  struct Iterator {
    std::size_t i;
    std::size_t operator*() const { return i; }
    Iterator& operator++() { return ++i, *this; }
    bool operator!=(const Iterator& other) const { return i != other.i; }
  };
  Iterator begin() const { return {0}; }
  Iterator end() const { return {n}; }
};

}  // namespace

Validity check_validity(const AbstractKnowledge& knowledge, const Kappa& kappa, const scenario::EnvironmentState& state,
                        std::span<const scenario::RobotContact> contacts, ValidityMode mode) {
  return check(knowledge, kappa, state, contacts, mode, AllBodies{state.movable_poses.size()});
}

Validity check_validity_after_step(const AbstractKnowledge& knowledge, const Kappa& kappa,
                                   const scenario::EnvironmentState& state,
                                   std::span<const scenario::RobotContact> contacts, ValidityMode mode,
                                   std::span<const int> moved) {
  return check(knowledge, kappa, state, contacts, mode, moved);
}

bool within_robot_limits(const RobotCapabilities& robot, const scenario::EnvironmentState& state) {
  const double slack = 1.0 + kLimitTolerance;
  // A holonomic robot's heading is held, not driven: it has no turn rate to bound.
  const bool turns_within = robot.drive == scenario::Drive::kHolonomic ||
                            std::abs(state.robot_turn_rate) <= robot.max_turn_rate * slack;
  return state.robot_velocity.norm() <= robot.max_speed * slack && turns_within;
}

int face_pushed_from(const AbstractKnowledge& knowledge, int body, const geometry::Pose2& pose,
                     const geometry::Vec2& robot_centre) {
  const MovableBodyKnowledge& b = knowledge.movable_bodies.at(static_cast<size_t>(body));
  int nearest = -1;
  double best = std::numeric_limits<double>::infinity();
  for (int face = 0; face < b.faces; ++face) {
    const std::optional<MRegionTemplate> touchable = kind_of(b.footprint.shape).face_template(b.footprint.shape, face, 0.0, knowledge.robot.radius);
    if (!touchable) continue;
    const MRegionTemplate& m = *touchable;
    const geometry::Vec2 from = geometry::to_world(pose, m.contact_from), to = geometry::to_world(pose, m.contact_to);
    const geometry::Vec2 along = to - from;
    const double t = along.squaredNorm() > 0 ? std::clamp((robot_centre - from).dot(along) / along.squaredNorm(), 0.0, 1.0) : 0.0;
    const double distance = (robot_centre - (from + t * along)).norm();
    if (distance < best) best = distance, nearest = face;
  }
  return nearest;
}

bool is_valid(const AbstractKnowledge& knowledge, const Kappa& kappa, const scenario::EnvironmentState& state,
              std::span<const scenario::RobotContact> contacts, ValidityMode mode) {
  return check_validity(knowledge, kappa, state, contacts, mode).valid();
}

}  // namespace physltl::knowledge
