#pragma once
// Formula progression (Bacchus and Kabanza): what must still hold from the next letter on, after a letter
// was read. A trace a1 a2 ... satisfies f exactly when a2 ... satisfies progress(f, a1). Execution with
// replanning hands the planner the task progressed over the letters executed so far (docs/robustness.md).

#include "physltl/ltl/formula.h"

#include <string>
#include <vector>

namespace physltl::ltl {

// `letter`: the propositions true at this step (a region's name, facts such as "B1@dock"). The result is
// simplified by constants (true & g = g, false | g = g, !true = false) and repeated operands, so it stays
// the size of f's subformulas however long the trace: true when the letters read already satisfy f
// whatever follows, false when nothing that follows can.
Formula progress(const Formula& f, const std::vector<std::string>& letter);

}  // namespace physltl::ltl
