#pragma once
// When a state of OMPL's search satisfies the task, and how far it is from doing so.

#include "physics_space.h"

#include "physltl/planning/propagation/checked_simulation.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/planning/plan.h"

#include <ompl/base/Goal.h>
#include <ompl/control/planners/ltl/Automaton.h>
#include <ompl/control/planners/ltl/LTLSpaceInformation.h>

#include <optional>
#include <vector>

namespace physltl::planners::ompl {

// On OMPL's product: reached when the co-safe automaton accepts. OMPL's own goal for the product has no
// distance (every state reads as infinitely far, which leaves KPIECE1 nothing to prefer); this one gives
// the automaton's distance to acceptance.
class TaskGoal : public ob::Goal {
 public:
  TaskGoal(const oc::LTLSpaceInformationPtr& si, const oc::AutomatonPtr& automaton)
      : ob::Goal(si), ltl_(si), automaton_(automaton) {}
  bool isSatisfied(const ob::State* state) const override { return isSatisfied(state, nullptr); }
  bool isSatisfied(const ob::State* state, double* distance) const override;

 private:
  oc::LTLSpaceInformationPtr ltl_;
  oc::AutomatonPtr automaton_;
};

// On our product: an accepting automaton state; for a task that must end at rest, one from which braking
// (zero set-points) brings the robot and the boxes to rest with every step valid and the automaton
// accepting there, as our tree search judges it.
class ProductGoal : public ob::Goal {
 public:
  ProductGoal(const ob::SpaceInformationPtr& si, const PhysicsSpace& space, const knowledge::AbstractKnowledge& knowledge);
  bool isSatisfied(const ob::State* state) const override { return isSatisfied(state, nullptr); }
  bool isSatisfied(const ob::State* state, double* distance) const override;

  // The braking controls from `state` to rest and the states after them, for a task that ends at rest
  // (none for one that does not); nothing when braking fails.
  std::optional<planning::Plan> braking(const ob::State* state) const;

 private:
  const PhysicsSpace& space_;
  mutable planning::CheckedSimulation simulation_;
};

}  // namespace physltl::planners::ompl
