#pragma once
// An LTL formula: an immutable tree of shared nodes, compared by structure.
//
// Conjunctions and disjunctions are n-ary and flattened on construction (a & (b & c) is one node with
// three operands, in the order given), so structural equality already treats them as associative.
// Each node remembers where its operator came from in the source text (`Origin`), which error messages
// use; the origin takes no part in equality, ordering or hashing.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace physltl::ltl {

enum class Op : std::uint8_t {
  True,
  False,
  Atom,
  Not,
  Next,           // X
  Finally,        // F
  Globally,       // G
  And,            // n-ary
  Or,             // n-ary
  Xor,            // ^
  Implies,        // ->
  Equiv,          // <->
  Until,          // U
  Release,        // R
  WeakUntil,      // W
  StrongRelease,  // M
};

// The operator's usual spelling, e.g. "U" or "->".
const char* spelling(Op op);

// Where a node comes from: the 1-based column (in characters) of its operator in the parsed text, and
// the operator as written there. Rewriting keeps both, so `!F a` in positive normal form is a G whose
// origin is the F at column 2. Column 0 means "not from any text".
struct Origin {
  std::uint32_t column = 0;
  Op written = Op::True;
};

class Formula {
 public:
  static Formula tt();
  static Formula ff();
  // Throws std::invalid_argument for a name that cannot be printed back (empty, or containing '"' or a
  // control character).
  static Formula atom(std::string name, Origin origin = {});
  static Formula unary(Op op, Formula operand, Origin origin = {});                 // Not, Next, Finally, Globally
  static Formula binary(Op op, Formula left, Formula right, Origin origin = {});    // any binary operator
  static Formula nary(Op op, std::vector<Formula> operands, Origin origin = {});    // And, Or; 0 or 1 operands fold

  Op op() const;
  const std::string& name() const;  // for atoms; empty otherwise
  std::span<const Formula> children() const;
  const Formula& child(std::size_t i) const { return children()[i]; }
  Origin origin() const;
  bool is_constant() const { return op() == Op::True || op() == Op::False; }
  std::size_t hash() const;
  std::size_t depth() const;  // 1 for a leaf

  friend bool operator==(const Formula& a, const Formula& b);
  friend std::strong_ordering operator<=>(const Formula& a, const Formula& b);

 private:
  struct Node;
  explicit Formula(std::shared_ptr<const Node> node) : node_(std::move(node)) {}
  static Formula make(Op op, std::string name, std::vector<Formula> children, Origin origin);
  std::shared_ptr<const Node> node_;
};

// Spot-style text with the fewest parentheses that parse back to the same formula, e.g.
// "F(p1 & F p2) | !p3 U p4".
std::string to_string(const Formula& f);
std::ostream& operator<<(std::ostream& out, const Formula& f);

// The atomic propositions of `f`, each once, in order of first occurrence from left to right.
std::vector<std::string> propositions(const Formula& f);

// The propositions that a formula in positive normal form mentions only negated (`!hazard`): the regions a
// task avoids, in order of first occurrence. Operands of `<->` and `^` count as both.
std::vector<std::string> avoided_propositions(const Formula& pnf);

}  // namespace physltl::ltl

template <>
struct std::hash<physltl::ltl::Formula> {
  std::size_t operator()(const physltl::ltl::Formula& f) const noexcept { return f.hash(); }
};
