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

#include <cstddef>
#include <stdexcept>

namespace physltl::ltl {

// The most states the construction explores before minimising, the most formulas it makes on the way
// (states are formulas; the successors of one state for every letter are made at once), and the most cubes
// its edges' labels are made of. Tasks that would need more ask for many things in any order or again and
// again: `F a1 & ... & F a20` (2^20 states) took 22 GB before the kernel ended the run, `G(a1 -> F b1) &
// ... & G(a11 -> F b11)` ran past 60 s and 5.5 GB making labels. Within the bounds: coverage of 11 regions
// (2,048 states, 177,147 edges, 0.07 s), 7 such obligations (129 states, 16,512 edges); one more of
// either is refused, in at most 0.6 s. No planner could search the product of more.
inline constexpr std::size_t kMaxAutomatonStates = 10'000;
inline constexpr std::size_t kMaxFormulas = 100'000;
inline constexpr std::size_t kMaxLabelCubes = 200'000;

// A formula whose automaton would have more than kMaxAutomatonStates states: the author's to change.
class AutomatonTooLarge : public std::runtime_error {
 public:
  AutomatonTooLarge();
};

// The alphabet is propositions(f), in that order. Any LTL formula. Throws AutomatonTooLarge.
Dfa translate(const Formula& f);

}  // namespace physltl::ltl
