#pragma once
// The syntactically co-safe class: the formulas every run of which that satisfies them does so after a
// finite prefix (a good prefix the search can stop at). Other tasks are read as "stop and stay"
// (task_class.h).
//
// In positive normal form such a formula uses only literals, true, false, &, |, X, F, U and M; `<->` and
// `^` are accepted between operands made of literals, constants, &, |, X and themselves (their negations
// stay in the class). G, R and W are refused unless constant folding removed them (G true, a R true,
// true W b, ...).

#include "physltl/ltl/formula.h"

#include <cstdint>
#include <optional>
#include <string>

namespace physltl::ltl {

// The first (leftmost, outermost) operator that takes a PNF formula outside the class.
struct CoSafetyViolation {
  Op op;          // the operator in positive normal form, e.g. G
  Origin origin;  // where it was written and as what, e.g. the F at column 2 of `!F a`
  Op context;     // Op::True, or the <-> / ^ whose operand it is (which needs it negated too)
  std::string message() const;  // "F at column 2 is negated, so it is G (always) in positive normal form: ..."
};

std::optional<CoSafetyViolation> find_co_safety_violation(const Formula& pnf);

}  // namespace physltl::ltl
