#pragma once
// Reads LTL in Spot's syntax, plus the paper's `<>`/`[]` and the symbols ◇ □ ○ ¬ ∧ ∨ → ↔ (UTF-8).
//
// Precedence, loosest first (as in Spot): `-> => <-> <=>` (right-associative), `| ||`, `^` (left),
// `& &&`, `U R W M` (right-associative), then the prefix operators `! X F G`. Atoms are identifiers
// starting with a letter or `_` (p1, kitchen, pi_3) or any text in double quotes; `true 1 false 0` are
// the constants. As in Spot, a word made of leading F/G/X letters and a lower-case rest is split:
// `GFa` is G(F(a)); quote a name to keep it whole ("Fridge").

#include "physltl/ltl/formula.h"

#include <cstdint>
#include <stdexcept>
#include <string_view>

namespace physltl::ltl {

// what() reads "column 7: expected ')' to close the '(' at column 3, but found 'b'".
class ParseError : public std::runtime_error {
 public:
  ParseError(std::uint32_t column, const std::string& message);
  std::uint32_t column() const { return column_; }  // 1-based, in characters

 private:
  std::uint32_t column_;
};

// Deeper nesting is refused, so that no input can exhaust the stack of this or later passes.
inline constexpr std::size_t kMaxFormulaDepth = 1000;

// Throws ParseError; never crashes, whatever the bytes.
Formula parse(std::string_view text);

}  // namespace physltl::ltl
