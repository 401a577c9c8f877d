#pragma once
// One thread's share of the search: from a tree node, sample a control towards a target point and
// propagate it through ODE step by step under the validity checker and INFERENCE. Each grower owns its
// ODE world, kappa and scratch space. What it grows depends only on the node, the target and the seed,
// never on the grower's history, which is what lets several threads expand one tree and still give a
// seed's plan exactly.

#include "physltl/planning/propagation/checked_simulation.h"
#include "physltl/planning/propagation/control_sampler.h"
#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/validity.h"
#include "physltl/physics/simulation.h"
#include "object_lead.h"
#include "physltl/planning/refusal.h"
#include "physltl/planning/task.h"
#include "product_graph.h"
#include "physltl/planning/stage_graph.h"
#include "push_plan_lead.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace physltl::planners::knowledge {

// A node of the search tree: the state after `control` from `parent`.
struct Motion {
  physics::PhysicsState state;
  geometry::Vec2 robot = geometry::Vec2::Zero();
  int parent = -1;
  planning::Control control;
  int stage = 0;  // the automaton's state and the named bodies' places (stage_graph.h)
  int product_state = 0;
};

// What one expansion grew: a chain of motions, the first a child of the node grown from, each next a
// child of the one before (their `parent` is left for the tree to fill in); empty when the first step was
// already invalid. One motion for a sampled control; a push primitive's controls one by one; and, for a
// task that ends at rest, after a motion that reached acceptance, the robot braking until it and the
// boxes stand still, still accepted, in controls of at most the scenario's max_steps each.
struct Growth {
  std::vector<Motion> motions;
  bool accepted = false;  // the last motion (after its braking, where the task needs it) reached acceptance
  int controls = 0;       // controls propagated, braking not counted
  int physics_steps = 0;
  bool stopped_by_invalid_step = false;
  std::optional<planning::Refusal> refusal;  // the rule that ended the motion (or its braking), if one did
  bool route_choice_cut = false;   // or the route choice did (OwnRefusal::kRouteChoiceCut)
};

// How an expansion samples its control and what it may touch.
enum class Guidance {
  kPushing,     // the knowledge sampler, pushing where a push helps towards the target
  kPushingTo,   // the same, each control ending where the robot gets to the target (the look-ahead's pushes)
  kGoingRound,  // the knowledge sampler steering only; touching a body the task does not name is cut
  kWidened,     // as the baseline grows: a uniform control, nothing cut but what the task and the world forbid
  kFollowingOrder,  // the look-ahead's push primitive: its order carried out control by control (push_plan_lead.h)
};

class TreeGrower {
 public:
  TreeGrower(const scenario::World& world, const planning::TaskAutomaton& task, const planning::StageGraph& stages,
             const physltl::knowledge::AbstractKnowledge& knowledge, const decomposition::Decomposition& decomposition,
             const ProductGraph& graph, const ObjectLead& object_lead, bool use_knowledge);

  // Replaces `growth` with what grows from `from` towards `target`, drawing from a generator seeded with
  // `seed`. With an object goal the target is where that goal's body move needs the robot (object_lead.h),
  // found in `from`'s state.
  void grow(const Motion& from, const geometry::Vec2& target, const ObjectLead::Goal* goal, Guidance guidance,
            std::uint64_t seed, Growth& growth);
  // Replaces `growth` with the push primitive's chain from `from`, which stands at push `push` of `order`:
  // one control of min_steps to max_steps steps at a time, each from the state the last left, until the
  // order is done, a step is refused, the state leaves the order, or kMaxPrimitiveStall controls pass
  // without getting closer to its end.
  void follow_order(const Motion& from, const PushPlanLead& order, int push, Growth& growth);

 private:
  // Applies `control` from the simulation's current state until the end, an invalid step, a dead
  // automaton state or acceptance; the valid steps make the growth's next motion. Whether a motion may
  // follow it: the whole control was valid and did not accept, or it accepted (and braked where the task
  // needs it); then the simulation stands at the growth's end.
  bool propagate(const planning::Control& control, int stage, bool may_push, Growth& growth);
  // From an accepting motion's end: the drive's set-point zero until the robot and the boxes are at rest,
  // every step valid and the automaton still accepting at the end. Whether that worked.
  bool brake(int stage, Growth& growth);
  // One valid step under `control`, then INFERENCE; false when the step was invalid, or when it touched a
  // movable body the task does not name while `may_push` is false (the growth then says which rule).
  bool valid_step(const geometry::Vec2& setpoint, bool may_push, Growth& growth);
  // The stage after the physics step just taken, from `stage`; -1 when the automaton died.
  int stage_after_step(int stage) const;
  bool accepting(int stage) const { return task_.dfa.accepting[static_cast<std::size_t>(stages_.automaton_state_of(stage))]; }
  Motion make_motion(const planning::Control& control, int stage) const;

  const planning::TaskAutomaton& task_;
  const planning::StageGraph& stages_;
  const decomposition::Decomposition& decomposition_;
  const ProductGraph& graph_;
  const ObjectLead& object_lead_;
  const planning::ControlSampler sampler_;
  const int max_braking_steps_;
  const int max_control_steps_;
  const int min_control_steps_;
  const double step_size_;  // s per physics step
  const double max_speed_;  // the robot's, m/s
  std::vector<bool> named_;  // per movable body: the task says where it must be (touching it is never refused)
  planning::CheckedSimulation simulation_;
  physics::PhysicsState last_valid_;
};

}  // namespace physltl::planners::knowledge
