#pragma once
// SampleControlAndSteps of Algorithm 3. The baseline samples forces uniformly, as OMPL's control
// samplers do. Knowledge guidance steers towards the lead and, where the robot stands in an active
// mRegion of a body that is in the way, pushes that body along the direction the mRegion allows.

#include "physltl/knowledge/kappa.h"
#include "physltl/planning/plan.h"
#include "physltl/scenario/state.h"
#include "random.h"

namespace physltl::planning {

class ControlSampler {
 public:
  ControlSampler(const scenario::World& world, const knowledge::AbstractKnowledge& knowledge, bool use_knowledge);

  // `target`: a point further along the lead, where the search wants the robot to go.
  Control sample(const scenario::EnvironmentState& state, const knowledge::Kappa& kappa, const Vec2& target,
                 Random& random) const;

 private:
  Vec2 uniform_force(Random& random) const;
  bool push_towards(const scenario::EnvironmentState& state, const knowledge::Kappa& kappa, const Vec2& heading,
                    Random& random, Vec2& force) const;

  const scenario::World& world_;
  const knowledge::AbstractKnowledge& knowledge_;
  bool use_knowledge_;
  double max_force_;
};

}  // namespace physltl::planning
