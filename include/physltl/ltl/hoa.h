#pragma once
// The automaton in the Hanoi Omega-Automata format, v1, as Spot writes deterministic automata with
// state-based Büchi acceptance, so that Spot's `autfilt` reads it. The accepting sink loops on [t] and
// is marked {0}: an infinite word is accepted iff it has a good prefix.

#include "physltl/ltl/dfa.h"

#include <iosfwd>

namespace physltl::ltl {

void write_hoa(std::ostream& out, const Dfa& dfa);

}  // namespace physltl::ltl
