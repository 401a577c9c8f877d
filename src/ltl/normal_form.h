#pragma once
// Positive normal form (PNF): negations pushed down to the atoms.
//
// `->` becomes `|`; `!` swaps the dual pairs F/G, U/R, W/M and &/|, and passes through X; `<->` and `^`
// stay (a negation turns one into the other), so that nested equivalences do not grow exponentially.
// Constants are folded on the way (X true = true, F false = false, false U b = b, a R true = true,
// true W b = true, G true = true, ...), which is what lets harmless G, R, W disappear.
// Every node keeps the origin of the operator it was rewritten from.

#include "physltl/ltl/formula.h"

namespace physltl::ltl {

Formula positive_normal_form(const Formula& f);

// The positive normal form of !f.
Formula negated_normal_form(const Formula& f);

}  // namespace physltl::ltl
