#pragma once
// OMPL's propagator over our physics: ODE steps checked as our planner checks them (the knowledge layer's
// validity and INFERENCE), the step's verdict written into the state's flags for the validity checker.

#include "physics_space.h"

#include "physltl/planning/propagation/checked_simulation.h"
#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/planning/refusal.h"

#include <ompl/base/StateValidityChecker.h>
#include <ompl/control/StatePropagator.h>

#include <vector>

namespace physltl::planners::ompl {

// What the propagator did: restores, steps, and steps refused for landing beyond step_neighbours().
struct GuardCounts {
  long long restores = 0;  // propagations started from a state other than the last one reached
  long long steps = 0;
  long long skips = 0;
  planning::Refusals refused;  // refused steps by rule, as our tree search counts them (refusal.h)
};

// One propagation: OMPL asks once per step of its propagation step size. On OMPL's product a step that
// lands beyond step_neighbours() is refused; on ours (space.product()) the automaton reads the full letter
// of every step (the robot's region and where the named bodies are), and a step into a state with no way
// to acceptance is refused. OMPL usually continues from the state it was just given, so the simulation
// restores a state only when it is another one.
class PhysicsPropagator : public oc::StatePropagator {
 public:
  PhysicsPropagator(const oc::SpaceInformationPtr& si, const PhysicsSpace& space, const knowledge::AbstractKnowledge& knowledge,
                    const decomposition::Decomposition& decomposition, const std::vector<std::vector<int>>& neighbours,
                    GuardCounts& counts);

  void propagate(const ob::State* from, const oc::Control* control, double duration, ob::State* to) const override;
  bool canPropagateBackward() const override { return false; }

 private:
  const PhysicsSpace& space_;
  const decomposition::Decomposition& decomposition_;
  const std::vector<std::vector<int>>& neighbours_;
  GuardCounts& counts_;
  mutable planning::CheckedSimulation simulation_;
  mutable physics::PhysicsState saved_;
  mutable std::vector<double> last_;
  mutable bool at_last_ = false;
};

// A state is valid when the step that made it was, and stayed in OMPL's product graph.
class StepValidity : public ob::StateValidityChecker {
 public:
  StepValidity(const ob::SpaceInformationPtr& si, std::size_t values) : ob::StateValidityChecker(si), values_(values) {}
  bool isValid(const ob::State* state) const override {
    const double* v = state->as<PhysicsSpace::StateType>()->values;
    return v[values_ + kValid] == 1.0 && v[values_ + kBeyondGraph] == 0.0;
  }

 private:
  const std::size_t values_;
};

}  // namespace physltl::planners::ompl
