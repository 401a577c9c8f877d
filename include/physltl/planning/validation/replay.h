#pragma once
// The proof of a plan: run its controls again from the start in a fresh physics world and check what
// happens, independently of the search that produced it.

#include "physltl/base/deadline.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/validity.h"
#include "physltl/physics/simulation.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/task.h"
#include "physltl/scenario/state_trace.h"

#include <string>
#include <vector>

namespace physltl::planning {

// A step whose bodies overlapped deeper than every step before it.
struct StepOverlap {
  std::size_t step = 0;  // into Replay::states, the step into that state
  physics::Overlap overlap;
};

struct Replay {
  // One entry per physics step, the initial state first; each body kept where it changed.
  scenario::StateTrace states;
  std::vector<int> region_trace;     // the robot's region at each state, -1 outside every region
  // Where the bodies the formula names are at each state: the fact set of its labelling (labelling.h);
  // with region_trace, the letter the automaton reads.
  std::vector<int> facts_trace;
  std::vector<int> automaton_trace;  // state of the formula's automaton after reading each letter
  std::vector<bool> pushing;         // the robot touched a movable body during the step into this state
  int pushes = 0;                    // count_pushes of the states replayed
  // Movable bodies the plan left more than a centimetre or a degree from where they started, World order.
  std::vector<int> moved_bodies;

  bool reproduces_plan = false;  // every state after a control equals the planned one, bit for bit
  // With ReplayOptions::record_control_states: the physics state after each control past the prefix.
  std::vector<physics::PhysicsState> control_states;
  bool valid = false;            // every step passes the validity rules of the mode it was planned in
  // Each rule some step broke, once, in the order first broken (a step reports the first rule it breaks,
  // in check_validity's order: limits, workspace, fixed bodies, then kappa's).
  std::vector<knowledge::Violation> violations;
  std::vector<std::string> violation_messages;  // for each of them, the first step that broke it, in words
  // The trace of letters (the robot's region and the facts BODY@REGION) satisfies the formula as written,
  // by direct LTL semantics on the trace followed by its last letter forever (ltl::holds_when_staying); a
  // co-safe task's trace must also be a good prefix.
  bool accepted = false;
  // A task read as "stop and stay" ends with the robot and every box at rest; true for co-safe tasks.
  bool ends_at_rest = false;
  // Every control's set-point and step count lie within the robot's and the planner's bounds, the drive
  // never applied more than max_force, and at every step the robot kept max_speed (and max_turn_rate).
  bool within_limits = false;
  double peak_speed = 0.0;       // m/s, the robot's fastest step
  // The steps (indices into `states`, of the step into that state) whose constraints ODE's solver did not
  // solve (physics::Simulation::last_step_solved): reported, not refused (docs/physics.md).
  std::vector<std::size_t> unsolved_steps;
  // The steps that overlapped two bodies deeper than any before, in order (physics::Simulation::
  // last_overlap): the last is the plan's deepest overlap. A step deeper than the planner's max_overlap
  // makes the plan invalid (docs/physics.md, "No body sinks into another").
  std::vector<StepOverlap> deepening_overlaps;
  // The plan's deepest overlap of two bodies, in m: 0 when none ever overlapped.
  double deepest_overlap_m() const { return deepening_overlaps.empty() ? 0.0 : deepening_overlaps.back().overlap.depth; }
  std::string failure;           // why not, for people; empty when validated
  // "time limit" or "interrupted" when ReplayOptions::deadline stopped the replay before the plan's end:
  // nothing is known of the rest, so the plan is not validated.
  std::string cut_short;
  bool validated() const {
    return cut_short.empty() && reproduces_plan && valid && accepted && within_limits && ends_at_rest;
  }
};

// The first `controls` controls of a plan that `replay` validated, for a plan that begins with the same
// controls and states: its replay takes those steps from `replay` and starts at the state they end in.
struct ReplayedPrefix {
  const Replay& replay;
  std::size_t controls = 0;
};

struct ReplayOptions {
  knowledge::ValidityMode mode = knowledge::ValidityMode::kKnowledge;  // the rules every step must pass
  // Stop at the first step that fails a check, for callers that only need to know whether the plan
  // validates (the replay then holds the steps up to that one).
  bool stop_at_first_failure = false;
  const ReplayedPrefix* prefix = nullptr;  // steps already replayed, taken as they are
  base::Deadline deadline{};  // checked every few physics steps (Replay::cut_short)
  // Also read every body and infer kappa from scratch at every step, and fail the replay (not valid) where
  // the state, the verdict or kappa kept for the bodies that moved differ: the tests' proof that the
  // incremental way equals the paper's INFERENCE from scratch.
  bool audit_inference = false;
  // The plan holds states only for the prefix's controls (a candidate made of a kept part and new
  // controls): record the state after each later control (Replay::control_states) instead of comparing.
  bool record_control_states = false;
};

// Replays `plan` and checks it against `formula` (the task as written, not the simplified one the search
// used) and against the validity rules of `options.mode`. The automaton of `formula` only labels the trace
// for pictures and, for a co-safe task, says whether it is a good prefix; the verdict on the formula comes
// from its semantics.
Replay replay(const scenario::World& world, const Plan& plan, const TaskAutomaton& formula,
              const knowledge::AbstractKnowledge& knowledge, const ReplayOptions& options = {});

// Why `control` is outside what the robot can be asked, or "" when it is within its bounds.
std::string control_out_of_bounds(const scenario::World& world, const Control& control);

// Whether a body at `to` counts as moved from `from`: more than a centimetre or a degree away.
bool moved(const geometry::Pose2& from, const geometry::Pose2& to);

// The pushes of a replayed trace (`pushing` as Replay holds it), as a person counts them: a stretch of
// steps in which the robot touches movable bodies, contact lost for at most kPushContactGap_s (a pushed
// box runs ahead for a moment), that moves a body (moved()) from where it was before the stretch to where
// it is when the next stretch begins, or at the end (a knocked body slides on). Where one control ends and
// the next begins does not end a push; brushing past a body without moving it is none.
inline constexpr double kPushContactGap_s = 0.25;
int count_pushes(const scenario::StateTrace& states, const std::vector<bool>& pushing, double step_size);

// Region names along the trace ("p0" outside every region), as plan.json stores them.
std::vector<std::string> region_names(const scenario::World& world, const std::vector<int>& region_trace);

}  // namespace physltl::planning
