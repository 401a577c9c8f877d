#pragma once
// SampleControlAndSteps of Algorithm 3. The baseline samples drive set-points uniformly, as OMPL's
// control samplers do. Knowledge guidance steers towards the lead and, where the robot stands in an
// active mRegion of a body that is in the way, pushes that body along the direction the mRegion allows.
// A differential robot is steered by turning towards the wanted direction while it drives as far as it
// already faces it.

#include "physltl/knowledge/kappa.h"
#include "physltl/planning/plan.h"
#include "physltl/scenario/state.h"
#include "physltl/planning/random.h"

namespace physltl::planning {

class ControlSampler {
 public:
  ControlSampler(const scenario::World& world, const knowledge::AbstractKnowledge& knowledge, bool use_knowledge);

  // `target`: a point further along the lead, where the search wants the robot to go. `may_push`: false
  // where the task needs no push (the lead goes round the bodies), so the knowledge sampler only steers.
  // `stop_at_target`: the control no longer than it takes the robot to get to the target, so that a push
  // can end where the look-ahead wants its body.
  Control sample(const scenario::EnvironmentState& state, const knowledge::Kappa& kappa, const Vec2& target,
                 bool may_push, Random& random, bool stop_at_target = false) const;
  // A control as the baseline samples it: a uniform set-point for a uniform number of steps.
  Control sample_uniform(Random& random) const;
  // The set-point that moves the robot along the unit vector `direction` at up to `speed` for `steps`.
  Vec2 along(const scenario::EnvironmentState& state, const Vec2& direction, double speed, int steps) const;

 private:
  Vec2 uniform_setpoint(Random& random) const;
  // A push direction of a body the robot stands ready to push that helps towards `heading`.
  bool push_towards(const scenario::EnvironmentState& state, const knowledge::Kappa& kappa, const Vec2& heading,
                    Random& random, Vec2& direction) const;

  const scenario::World& world_;
  const knowledge::AbstractKnowledge& knowledge_;
  bool use_knowledge_;
  // Per movable body, how far from its centre any point of its mRegions lies: a body farther than that
  // from the robot has no mRegion the robot stands in, which saves placing them.
  std::vector<double> mregion_reach_;
};

}  // namespace physltl::planning
