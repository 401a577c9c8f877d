#pragma once
// How OMPL's planners sample controls: OMPL's uniform sampler with a seeded generator, or, as an option,
// the knowledge planner's (it reads the world and kappa at the state a control starts from and aims at a
// target, pushing a body in the way from an mRegion along an allowed direction).

#include "physics_space.h"

#include "physltl/planning/propagation/checked_simulation.h"
#include "physltl/planning/propagation/control_sampler.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/planning/random.h"

#include <ompl/control/ControlSampler.h>
#include <ompl/control/DirectedControlSampler.h>
#include <ompl/control/SpaceInformation.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>

#include <optional>

namespace physltl::planners::ompl {

// OMPL's uniform control sampler, with a generator seeded from the run's seed.
class SeededControlSampler : public oc::RealVectorControlUniformSampler {
 public:
  SeededControlSampler(const oc::ControlSpace* space, std::uint_fast32_t seed) : oc::RealVectorControlUniformSampler(space) {
    rng_.setLocalSeed(seed);
  }
};

class OurSampling {
 public:
  // `ompl_product`: the states are OMPL's product's (compound), else our physics space's.
  OurSampling(const scenario::World& world, const knowledge::AbstractKnowledge& knowledge, std::uint64_t seed,
              bool ompl_product);

  // Samples from `state` towards `target`, or towards a point drawn at random in the workspace; writes the
  // set-point into `control` and returns the control's steps.
  unsigned sample(oc::Control* control, const ob::State* state, const std::optional<geometry::Vec2>& target);

 private:
  const scenario::World& world_;
  const planning::ControlSampler sampler_;
  planning::CheckedSimulation simulation_;
  planning::Random random_;
  const bool ompl_product_;
};

// For KPIECE1 and LTLPlanner (which sample a control at a state, then its steps) and SST (which samples
// without a state: then uniformly, as OMPL's sampler does).
class OurControlSampler : public oc::ControlSampler {
 public:
  OurControlSampler(const oc::ControlSpace* space, const scenario::World& world,
                    const knowledge::AbstractKnowledge& knowledge, std::uint64_t seed, bool ompl_product)
      : oc::ControlSampler(space),
        sampling_(world, knowledge, seed, ompl_product),
        uniform_(space, static_cast<std::uint_fast32_t>(seed | 1u)) {}
  void sample(oc::Control* control) override { uniform_.sample(control); }
  void sample(oc::Control* control, const ob::State* state) override { steps_ = sampling_.sample(control, state, std::nullopt); }
  void sampleNext(oc::Control* control, const oc::Control*, const ob::State* state) override { sample(control, state); }
  unsigned int sampleStepCount(unsigned int min_steps, unsigned int max_steps) override {
    return steps_ >= min_steps && steps_ <= max_steps ? steps_ : uniform_.sampleStepCount(min_steps, max_steps);
  }

 private:
  OurSampling sampling_;
  SeededControlSampler uniform_;
  unsigned steps_ = 0;
};

// For RRT and PDST, which grow towards a sampled state: our sampler aims at it.
class OurDirectedSampler : public oc::DirectedControlSampler {
 public:
  OurDirectedSampler(const oc::SpaceInformation* si, const scenario::World& world,
                     const knowledge::AbstractKnowledge& knowledge, std::uint64_t seed, bool ompl_product)
      : oc::DirectedControlSampler(si), sampling_(world, knowledge, seed, ompl_product), ompl_product_(ompl_product) {}
  unsigned int sampleTo(oc::Control* control, const ob::State* source, ob::State* dest) override;
  unsigned int sampleTo(oc::Control* control, const oc::Control*, const ob::State* source, ob::State* dest) override {
    return sampleTo(control, source, dest);
  }

 private:
  OurSampling sampling_;
  const bool ompl_product_;
};

}  // namespace physltl::planners::ompl
