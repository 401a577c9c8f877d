#pragma once
// Direct LTL semantics on an ultimately periodic word u v^omega (a lasso), written from the definitions
// and sharing no code with the automaton translation: the independent check of a plan's region trace.

#include "physltl/ltl/formula.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace physltl::ltl {

// letters[i]: the propositions true at position i. Positions loop_start..end repeat forever; loop_start
// must be a position of `letters`, which must not be empty. Whether the word satisfies `f` at position 0.
bool holds_on_lasso(const Formula& f, std::span<const std::vector<std::string>> letters, std::size_t loop_start);

// The "stops and stays" reading of a finite trace: the trace followed by its last letter forever.
bool holds_when_staying(const Formula& f, std::span<const std::vector<std::string>> trace);

}  // namespace physltl::ltl
