#pragma once
// Co-safe LTL -> the minimal deterministic complete automaton of its good prefixes.
//
// A finite trace is accepted exactly when every infinite continuation of it satisfies the formula, so
// `F a | X F !a` (true of every infinite word) gives one accepting state. Construction: formula
// progression with states as normalised formulas (minimal DNFs over temporal subformulas), the
// successors of a state computed symbolically for all letters at once as a decision diagram over the
// propositions; a state accepts when no infinite path from it avoids the state `true`; then Moore
// partition refinement. All accepting states collapse into one accepting sink.

#include "physltl/ltl/dfa.h"
#include "physltl/ltl/formula.h"

namespace physltl::ltl {

// The alphabet is propositions(f), in that order. Throws NotCoSafeError for a formula outside the
// syntactically co-safe class.
Dfa translate(const Formula& f);

}  // namespace physltl::ltl
