#pragma once
// The paper's VALIDITYCHECKER rules as a function of (state, contacts, kappa), so the planner and the
// tests call the same code, with or without physics.

#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/scenario/state.h"

#include <span>

namespace physltl::knowledge {

enum class ValidityMode {
  kKnowledge,  // every rule below
  kBaseline,   // plain physics-based planning (--baseline): only the world's rules count (the robot's
               // limits, fixed-body contacts, leaving the workspace, and a push from a face the body's
               // push_from does not list), and kappa is not read (an empty Kappa will do)
};

enum class Violation {
  kNone,
  kExceedsRobotLimits,          // faster than max_speed or turning faster than max_turn_rate
  kLeftWorkspace,               // the robot or a movable body is (partly) outside the workspace
  kTouchesFixedBody,            // a wall or other fixed body
  kTouchesImmovableBody,        // a movable body kappa types immovable (blocked on all sides, or too heavy)
  kPushesFromForbiddenSide,     // a constraint-oriented body, robot centre outside its active mRegions
                                // (baseline: outside every face its push_from lists)
  kBodiesOverlap,               // two bodies (the robot, a movable or a fixed one) overlap deeper than the
                                // planner's max_overlap where the step ended: found by the physics
                                // (planning::CheckedSimulation), never by check_validity
};
const char* violation_name(Violation violation);

struct Validity {
  Violation violation = Violation::kNone;
  // The body at fault: index into World::fixed_bodies for kTouchesFixedBody, into World::movable_bodies
  // otherwise; -1 for none or for the robot leaving the workspace.
  int body_index = -1;

  bool valid() const { return violation == Violation::kNone; }
  bool operator==(const Validity&) const = default;
};

// How far a body may poke out of the workspace before it counts as having left (contact solvers let
// bodies sink into walls by a fraction of a millimetre).
inline constexpr double kWorkspaceTolerance = 1e-3;  // m
// How far beyond the ends of an active mRegion the robot's centre may be and still push from that side. A
// robot working a box along a 0.6 m lane brushes its corners with its centre just past the mRegion; without
// this, grid push puzzles the baseline solves were lost (docs/planner.md, "Cuts and biases"). Larger values
// admit pushes at the corner itself, which slip in worlds heavier than modelled.
inline constexpr double kPushSideSlack = 0.1;  // m
// How much faster than its declared limits the robot may move: ODE's contact correction can add a little
// velocity of its own (physics::Simulation), and the integrator rounds.
inline constexpr double kLimitTolerance = 0.01;  // relative

// Whether the robot's speed and turn rate in `state` keep the limits in K (within kLimitTolerance).
bool within_robot_limits(const RobotCapabilities& robot, const scenario::EnvironmentState& state);

Validity check_validity(const AbstractKnowledge& knowledge, const Kappa& kappa,
                        const scenario::EnvironmentState& state,
                        std::span<const scenario::RobotContact> contacts,
                        ValidityMode mode = ValidityMode::kKnowledge);

// The face of movable body `body` (scenario::face_count numbers them) at `pose` that the robot's centre is
// nearest to touching: the face a push from there comes through, for messages.
int face_pushed_from(const AbstractKnowledge& knowledge, int body, const geometry::Pose2& pose,
                     const geometry::Vec2& robot_centre);

bool is_valid(const AbstractKnowledge& knowledge, const Kappa& kappa, const scenario::EnvironmentState& state,
              std::span<const scenario::RobotContact> contacts, ValidityMode mode = ValidityMode::kKnowledge);

// The same after one step from a valid state in which only the movable bodies `moved` (indices) can have
// moved: the others are still inside the workspace, so only these are tested there. The planner's
// propagation knows them from the physics; the verdict is the one of check_validity.
Validity check_validity_after_step(const AbstractKnowledge& knowledge, const Kappa& kappa,
                                   const scenario::EnvironmentState& state,
                                   std::span<const scenario::RobotContact> contacts, ValidityMode mode,
                                   std::span<const int> moved);

}  // namespace physltl::knowledge
