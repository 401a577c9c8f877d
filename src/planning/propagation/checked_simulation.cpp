#include "physltl/planning/propagation/checked_simulation.h"

namespace physltl::planning {

CheckedSimulation::CheckedSimulation(const scenario::World& world, const knowledge::AbstractKnowledge& knowledge,
                                     knowledge::ValidityMode mode)
    : knowledge_(knowledge), mode_(mode), max_overlap_(world.planner.max_overlap), simulation_(world) {}

void CheckedSimulation::restore(const physics::PhysicsState& state) {
  simulation_.restore(state);
  if (kappa_valid_) {
    // Only the robot and the bodies whose state differs from the last one changed: read and infer for those.
    simulation_.update_environment(environment_);
    knowledge::reinfer(knowledge_, environment_, kappa_poses_, kappa_, simulation_.last_movers());
  } else {
    simulation_.read_environment(environment_);
    knowledge::infer(knowledge_, environment_, kappa_);
    kappa_poses_ = knowledge::BodyLocator(knowledge_, environment_.movable_poses);
    kappa_valid_ = true;
  }
}

knowledge::Validity CheckedSimulation::step(const scenario::Vec2& setpoint) {
  simulation_.step(setpoint, contacts_);
  // Only the robot and the bodies the step integrated changed: read, test and infer for those.
  simulation_.update_environment(environment_);
  const std::span<const int> movers = simulation_.last_movers();
  // VALIDITYCHECKER(E_new, kappa_j), then kappa_{j+1} = INFERENCE(E_new, kappa_j).
  knowledge::Validity validity =
      knowledge::check_validity_after_step(knowledge_, kappa_, environment_, contacts_, mode_, movers);
  if (mode_ == knowledge::ValidityMode::kKnowledge) knowledge::reinfer(knowledge_, environment_, kappa_poses_, kappa_, movers);
  // The world forbids it whatever the mode: a body is never inside another.
  if (validity.valid() && simulation_.last_overlap().depth > max_overlap_) validity.violation = knowledge::Violation::kBodiesOverlap;
  return validity;
}

}  // namespace physltl::planning
