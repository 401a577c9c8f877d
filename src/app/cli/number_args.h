#pragma once
// The checks of numbers given on the command line: finite and in range, with the same words as a
// scenario's numbers (scenario::number_problem), and seeds as whole numbers written as such.

#include <CLI/CLI.hpp>

namespace physltl::app {

// A number from lo to hi (lo itself allowed or not): NaN, infinities and numbers out of range refused.
CLI::Validator number_in(double lo, double hi, bool lo_allowed = false);

// A whole number from lo to hi, written as one (digits, a leading minus sign): "two", "1.5" and numbers out
// of range refused with the value and the range as a person writes them.
CLI::Validator whole_in(long long lo, long long hi);

// A seed: a whole number from 0 to 2^64 - 1, digits only ("-1" is refused, not wrapped round).
CLI::Validator seed_number();

}  // namespace physltl::app
