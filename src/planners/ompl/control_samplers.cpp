#include "control_samplers.h"

namespace physltl::planners::ompl {

using geometry::Vec2;

OurSampling::OurSampling(const scenario::World& world, const knowledge::AbstractKnowledge& knowledge, std::uint64_t seed,
                         bool ompl_product)
    : world_(world),
      sampler_(world, knowledge, true),
      simulation_(world, knowledge, knowledge::ValidityMode::kKnowledge),
      random_(seed),
      ompl_product_(ompl_product) {}

unsigned OurSampling::sample(oc::Control* control, const ob::State* state, const std::optional<Vec2>& target) {
  const double* v = physics_values(state, ompl_product_);
  simulation_.restore(
      physics::PhysicsState::from_values({v, (world_.movable_bodies.size() + 1) * physics::PhysicsState::kValuesPerBody}));
  const auto& b = world_.workspace.bounds;
  const Vec2 aim = target ? *target : Vec2(random_.uniform(b.min.x(), b.max.x()), random_.uniform(b.min.y(), b.max.y()));
  const planning::Control c = sampler_.sample(simulation_.environment(), simulation_.kappa(), aim, true, random_);
  set_control(control, c.setpoint, world_.robot.drive == scenario::Drive::kDifferential);
  return static_cast<unsigned>(c.steps);
}

unsigned int OurDirectedSampler::sampleTo(oc::Control* control, const ob::State* source, ob::State* dest) {
  const double* d = physics_values(dest, ompl_product_);
  const unsigned steps = sampling_.sample(control, source, Vec2(d[0], d[1]));
  return si_->propagateWhileValid(source, control, static_cast<int>(steps), dest);
}

}  // namespace physltl::planners::ompl
