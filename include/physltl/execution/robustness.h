#pragma once
// How well an open-loop plan survives a world that is not quite the model: its controls replayed in
// perturbed worlds (perturbation.h), each judged as the plan's own replay is, but for reproducing the
// planned states (docs/robustness.md).

#include "physltl/base/deadline.h"
#include "physltl/knowledge/validity.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/planning/task.h"

#include <cstdint>
#include <map>
#include <string>

namespace physltl::execution {

// The ways a perturbed world's run goes wrong, as report.json names them. A world fails on any of the
// first six; the last two (kappa's rules on pushing) are counted but do not fail a world on their own.
inline constexpr const char* kFailureKinds[] = {
    "push_missed",         // a body the plan moves did not move
    "box_elsewhere",       // the formula failed and a body the plan moves ended over 0.1 m from where it did
    "region_not_reached",  // the formula failed otherwise (or without a nominal replay to compare with)
    "left_workspace",      // the robot or a body left the workspace
    "touched_fixed_body",  // the robot touched a wall or another fixed body
    "beyond_limits",       // the robot broke a declared limit (speed, turn rate, force)
    "not_at_rest",         // a stop-and-stay task ended with the robot or a box moving
    "touched_immovable_body",  // kappa: a body it types immovable
    "forbidden_push_side",     // kappa: a constraint-oriented body pushed from outside its active mRegions
};

struct WorldRun {
  bool cut_short = false;             // the deadline stopped its replay: nothing known of this world
  bool succeeded = false;
  std::vector<std::string> failures{};  // kinds, in kFailureKinds' order
  std::string first_failure{};        // for people: the rule broken (with its step) or else how the task failed
};

// One perturbed world's run of `plan`, against `nominal`, the plan's replay in the model, which tells a
// push that missed and a box that ended elsewhere from a region not reached; without it (controls that
// no single plan made, such as an execution's) a failed formula counts as region_not_reached.
WorldRun judge_in_world(const scenario::World& world, const planning::Plan& plan, const planning::Replay* nominal,
                        const planning::TaskAutomaton& formula, const base::Deadline& deadline = {});

struct Robustness {
  int asked = 0;         // worlds asked for
  int worlds = 0;        // worlds judged: fewer than asked when the deadline stopped the measure
  std::string stopped;   // "time limit" or "interrupted" then, else empty
  int succeeded = 0;
  std::map<std::string, int> failures;  // kind -> worlds with it
  double share() const { return worlds > 0 ? static_cast<double>(succeeded) / worlds : 0.0; }
};

// `worlds` perturbed worlds of `model` (indices 0..worlds-1 of `seed`), each judged by judge_in_world,
// until `deadline`: the worlds judged by then (Robustness::stopped says why it stopped). Throws
// PerturbationError when the uncertainty admits no valid world.
Robustness measure_robustness(const scenario::World& model, const scenario::Uncertainty& uncertainty, int worlds,
                              std::uint64_t seed, const planning::Plan& plan, const planning::Replay& nominal,
                              const planning::TaskAutomaton& formula, const base::Deadline& deadline = {});

}  // namespace physltl::execution
