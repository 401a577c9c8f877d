#pragma once
// What the knowledge layer and the LTL module conclude about a World before any planning: the paper's K,
// kappa_0, F(K, Pi) -> M_p and the task simplified by M_p with its automaton. `check` reports it; the
// planner starts from it.

#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/feasibility.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/ltl/analysis.h"
#include "physltl/scenario/state.h"
#include "physltl/scenario/world.h"

#include <optional>

namespace physltl::knowledge {

struct Reasoning {
  AbstractKnowledge knowledge;    // K
  scenario::EnvironmentState initial_state;  // E_0: everything where the scenario put it
  Kappa initial_kappa;            // kappa_0 = INFERENCE(K, E_0)
  Feasibility feasibility;        // M_p: the invalid propositions, with reasons
  // The task: as written, in positive normal form, simplified by M_p (the paper's list rule for
  // information, the semantic rule the planner uses) and the DFA of the simplified task (empty when
  // infeasible).
  ltl::Analysis task;

  bool feasible() const { return task.feasible(); }
  // The formula the planner gets: the semantic simplification, or the normal form when no proposition is
  // invalid; empty when the task is infeasible.
  std::optional<ltl::Formula> simplified_formula() const;
};

// Pure and deterministic until `deadline` comes; after it, the object propositions not yet judged stay
// reachable (evaluate_feasibility). Expects a World that passed scenario validation (its formula parses and
// names only its regions); otherwise throws ltl::ParseError.
Reasoning reason_about(const scenario::World& world, const base::Deadline& deadline = {});

}  // namespace physltl::knowledge
