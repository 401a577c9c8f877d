#pragma once
// Everything the `physltl-studio ltl` command shows about a formula, computed by one pure function so
// that the command stays a thin shell and its behaviour is testable.

#include "physltl/ltl/dfa.h"
#include "physltl/ltl/formula.h"
#include "physltl/ltl/simplify.h"
#include "physltl/ltl/task_class.h"

#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace physltl::ltl {

struct Analysis {
  Formula input;
  Formula normal_form;                     // positive normal form
  TaskClass task_class = TaskClass::kCoSafe;  // of the task the planner gets (of the input when infeasible)
  std::vector<std::string> invalid;        // as given
  std::vector<std::string> always_true;    // as given: propositions that hold on every run
  std::optional<Simplification> by_lists;  // the paper's Simplify, when `invalid` is not empty
  std::optional<Simplification> semantic;  // the planner's, when `invalid` or `always_true` is not empty
  std::optional<Dfa> dfa;                  // of the task the planner gets; empty when infeasible
  // Set when no run can satisfy the task because the robot, and each body, is in at most one region at a
  // time (the propositions are disjoint regions; src/ltl/exclusivity.h), found on the automaton without any
  // search, or (set by whoever knows the World, accepts_after) because its first letter already loses
  // it: why, for people.
  std::optional<std::string> unsatisfiable;

  bool feasible() const { return (!semantic || semantic->feasible()) && !unsatisfiable; }
  // Why the task is infeasible; empty when it is feasible.
  std::string infeasibility() const;
};

// Any LTL formula over propositions that are disjoint regions, the robot's and the bodies' (BODY@REGION).
// Throws ParseError for a syntax error.
// `always_true`: propositions that hold at every step of every run (a body that cannot move, standing in
// the region an object proposition names); the semantic simplification makes them true.
Analysis analyse(std::string_view text, std::span<const std::string> invalid,
                 std::span<const std::string> always_true = {});
// The same for a formula parsed already.
Analysis analyse(const Formula& input, std::span<const std::string> invalid, std::span<const std::string> always_true = {});

// Whether a run whose first letter is `first` (indices into dfa.propositions of those true at the start;
// the rest false) can still satisfy the task, over letters that can occur after it.
bool accepts_after(const Dfa& dfa, std::span<const int> first);

// Human-readable lines: input, normal form, class, simplifications, automaton size.
void write_summary(std::ostream& out, const Analysis& analysis);

}  // namespace physltl::ltl
