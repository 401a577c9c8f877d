#pragma once
// Feasibility evaluation and simplification of a task given propositions the robot can never make true
// (regions it cannot reach), after Muhayyuddin, Akbari and Rosell, "Physics-based Motion Planning with
// Temporal Logic Specifications", IFAC 2017, Algorithms 1 (Simplify) and 2 (Evaluate).

#include "physltl/ltl/formula.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace physltl::ltl {

struct Simplification {
  std::optional<Formula> formula;     // in positive normal form; empty when the task is infeasible
  std::vector<std::string> dropped;   // propositions of the input that the result no longer mentions
  std::string explanation;            // for people: what was dropped and why, or why it is infeasible
  bool feasible() const { return formula.has_value(); }
};

// The paper's list-based Simplify/Evaluate, on the positive normal form of `f`: from each occurrence of
// an invalid proposition walk up the formula tree; at the first operand of an `|` on the way, delete
// that operand; if the root comes first, the task is infeasible. It reads `!p` like `p`, so it rejects
// tasks that only avoid an unreachable region, e.g. `(F p1 | F p2) & !p3 U p1` with p3 invalid.
Simplification simplify_by_lists(const Formula& f, std::span<const std::string> invalid);

// The semantic version the planner uses: an invalid proposition is false at every step of every run,
// so substitute false for it (a visit `p3` cannot happen, an avoidance `!p3` always holds) and fold
// constants. A proposition that always holds (a body too heavy to push, standing in the region an object
// proposition names) becomes true the same way. Infeasible exactly when the result is false.
Simplification simplify_semantically(const Formula& f, std::span<const std::string> invalid,
                                     std::span<const std::string> always_true = {});

}  // namespace physltl::ltl
