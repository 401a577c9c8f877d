#pragma once
// LTL -> the minimal deterministic complete automaton of the finite traces that satisfy a task.
//
// A co-safe formula gets the automaton of its good prefixes: a finite trace is accepted exactly when
// every infinite continuation of it satisfies the formula, so `F a | X F !a` (true of every infinite
// word) gives one accepting state, and all accepting states collapse into one accepting sink. Any other
// formula gets the stop-and-stay automaton: a trace is accepted when it followed by its last letter
// forever satisfies the formula (Dfa::acceptance says which). Construction: formula progression with
// states as normalised formulas (minimal DNFs over temporal subformulas), the successors of a state
// computed symbolically for all letters at once as a decision diagram over the propositions; a co-safe
// state accepts when no infinite path from it avoids the state `true`, a stop-and-stay state when the
// formula before the last letter holds on that letter repeated; then Moore partition refinement.

#include "physltl/ltl/dfa.h"
#include "physltl/ltl/formula.h"

namespace physltl::ltl {

// The alphabet is propositions(f), in that order. Any LTL formula.
Dfa translate(const Formula& f);

}  // namespace physltl::ltl
