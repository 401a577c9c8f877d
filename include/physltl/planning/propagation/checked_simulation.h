#pragma once
// The physics as the planners see it: each step checked by the knowledge layer's VALIDITYCHECKER under
// the kappa of the state it started from, and kappa kept up to date by INFERENCE after each step, redone
// only for the bodies a move can affect. Our tree growers, the OMPL propagator and the replay step through
// it, so every planner is held to the same rules and the replay to the same checks. After an invalid step
// too: the replay goes on past one to report the rest (a planner restores another state instead, and
// pays for one body's inference).

#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/knowledge/validity.h"
#include "physltl/physics/simulation.h"

#include <vector>

namespace physltl::planning {

// How long a plan that must end at rest may brake for, in every planner: longer than any robot and box
// need to stop (the drive stops the robot within a step or two, floor friction a sliding box within a
// fraction of a second).
inline constexpr double kMaxBrakingTime = 3.0;  // s

class CheckedSimulation {
 public:
  CheckedSimulation(const scenario::World& world, const knowledge::AbstractKnowledge& knowledge,
                    knowledge::ValidityMode mode);

  // Puts the world in `state` and kappa in step with it.
  void restore(const physics::PhysicsState& state);
  // One physics step with the drive tracking `setpoint`; the rule it broke and the body at fault, kNone
  // for a valid step (after an invalid one the world stands in the invalid state, kappa inferred there).
  // Besides the knowledge layer's rules, two bodies overlapping deeper than the planner's max_overlap
  // where the step ended make it invalid (physics().last_overlap() names them).
  knowledge::Validity step(const scenario::Vec2& setpoint);
  void save(physics::PhysicsState& out) const { simulation_.save(out); }

  const scenario::EnvironmentState& environment() const { return environment_; }
  // The robot's contacts during the last step.
  const std::vector<scenario::RobotContact>& contacts() const { return contacts_; }
  const knowledge::Kappa& kappa() const { return kappa_; }
  // The physics under the checks: its drive, solver and the bodies the last step moved.
  const physics::Simulation& physics() const { return simulation_; }

 private:
  const knowledge::AbstractKnowledge& knowledge_;
  const knowledge::ValidityMode mode_;
  const double max_overlap_;  // m: a step whose bodies overlap deeper is invalid
  physics::Simulation simulation_;
  // Scratch space reused by every step, so the hot loop does not allocate.
  scenario::EnvironmentState environment_;
  knowledge::Kappa kappa_;
  knowledge::BodyLocator kappa_poses_;  // the poses kappa_ was inferred for
  bool kappa_valid_ = false;
  std::vector<scenario::RobotContact> contacts_;
};

}  // namespace physltl::planning
