#pragma once
// `--uncertainty mass=0.3,friction=0.1` (run, bench, execute): replaces the named values of the scenario's
// uncertainty { ... } and keeps the others (docs/robustness.md).

#include "physltl/scenario/world.h"

#include <string>

namespace physltl::setup {

// Throws BadInput naming the offending pair (an unknown key, a value that is not a number or out of range).
scenario::Uncertainty override_uncertainty(const scenario::Uncertainty& declared, const std::string& text);

}  // namespace physltl::setup
