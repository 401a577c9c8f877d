#include "normal_form.h"

#include <algorithm>

namespace physltl::ltl {

namespace {

bool is_true(const Formula& f) { return f.op() == Op::True; }
bool is_false(const Formula& f) { return f.op() == Op::False; }

Origin from(const Formula& f) { return f.origin(); }

// The smart constructors below fold constants and nothing else, so each rewrite is obviously sound.

Formula junction(Op op, std::vector<Formula> operands, Origin origin) {
  const Op unit = op == Op::And ? Op::True : Op::False;  // neutral element
  const Op zero = op == Op::And ? Op::False : Op::True;  // absorbing element
  std::vector<Formula> kept;
  for (Formula& f : operands) {
    if (f.op() == zero) return f;
    if (f.op() == unit) continue;
    // Flatten here so that duplicates nested one level down are found too.
    std::vector<Formula> parts = f.op() == op ? std::vector<Formula>(f.children().begin(), f.children().end())
                                              : std::vector<Formula>{f};
    for (Formula& p : parts)
      if (std::ranges::find(kept, p) == kept.end()) kept.push_back(std::move(p));
  }
  if (kept.size() == 1) return kept.front();
  return Formula::nary(op, std::move(kept), origin);
}

Formula temporal_unary(Op op, Formula f, Origin origin) {
  if (f.is_constant()) return f;  // X, F and G of a constant are that constant
  return Formula::unary(op, std::move(f), origin);
}

Formula pnf(const Formula& f, bool negated);

Formula until_like(Op op, Formula a, Formula b, Origin origin) {
  switch (op) {
    case Op::Until:  // a U b = b | (a & X(a U b))
      if (b.is_constant() || is_false(a)) return b;
      if (is_true(a)) return temporal_unary(Op::Finally, b, origin);
      break;
    case Op::Release:  // a R b = b & (a | X(a R b))
      if (b.is_constant() || is_true(a)) return b;
      if (is_false(a)) return temporal_unary(Op::Globally, b, origin);
      break;
    case Op::WeakUntil:  // a W b = b | (a & X(a W b))
      if (is_true(b) || is_true(a)) return Formula::tt();
      if (is_false(a)) return b;
      if (is_false(b)) return temporal_unary(Op::Globally, a, origin);
      break;
    case Op::StrongRelease:  // a M b = b & (a | X(a M b))
      if (is_false(b) || is_false(a)) return Formula::ff();
      if (is_true(a)) return b;
      if (is_true(b)) return temporal_unary(Op::Finally, a, origin);
      break;
    default: break;
  }
  return Formula::binary(op, std::move(a), std::move(b), origin);
}

// a <-> b (or a ^ b when `exclusive`) over operands already in PNF; the constant cases need the
// other operand negated, which for a PNF formula is another PNF pass.
Formula equivalence(bool exclusive, Formula a, Formula b, Origin origin) {
  if (a.is_constant()) std::swap(a, b);
  if (b.is_constant()) return is_true(b) != exclusive ? a : pnf(a, true);
  return Formula::binary(exclusive ? Op::Xor : Op::Equiv, std::move(a), std::move(b), origin);
}

Formula pnf(const Formula& f, bool negated) {
  const Origin origin = from(f);
  auto sub = [&](std::size_t i, bool neg) { return pnf(f.child(i), neg); };
  auto all = [&](bool neg) {
    std::vector<Formula> out;
    out.reserve(f.children().size());
    for (const Formula& c : f.children()) out.push_back(pnf(c, neg));
    return out;
  };
  switch (f.op()) {
    case Op::True: return negated ? Formula::ff() : f;
    case Op::False: return negated ? Formula::tt() : f;
    case Op::Atom: return negated ? Formula::unary(Op::Not, f, origin) : f;
    case Op::Not: return sub(0, !negated);
    case Op::Next: return temporal_unary(Op::Next, sub(0, negated), origin);
    case Op::Finally: return temporal_unary(negated ? Op::Globally : Op::Finally, sub(0, negated), origin);
    case Op::Globally: return temporal_unary(negated ? Op::Finally : Op::Globally, sub(0, negated), origin);
    case Op::And: return junction(negated ? Op::Or : Op::And, all(negated), origin);
    case Op::Or: return junction(negated ? Op::And : Op::Or, all(negated), origin);
    case Op::Implies:  // a -> b = !a | b
      return negated ? junction(Op::And, {sub(0, false), sub(1, true)}, origin)
                     : junction(Op::Or, {sub(0, true), sub(1, false)}, origin);
    case Op::Equiv: return equivalence(negated, sub(0, false), sub(1, false), origin);
    case Op::Xor: return equivalence(!negated, sub(0, false), sub(1, false), origin);
    case Op::Until: return until_like(negated ? Op::Release : Op::Until, sub(0, negated), sub(1, negated), origin);
    case Op::Release:
      return until_like(negated ? Op::Until : Op::Release, sub(0, negated), sub(1, negated), origin);
    case Op::WeakUntil:
      return until_like(negated ? Op::StrongRelease : Op::WeakUntil, sub(0, negated), sub(1, negated), origin);
    case Op::StrongRelease:
      return until_like(negated ? Op::WeakUntil : Op::StrongRelease, sub(0, negated), sub(1, negated), origin);
  }
  return f;
}

}  // namespace

Formula positive_normal_form(const Formula& f) { return pnf(f, false); }
Formula negated_normal_form(const Formula& f) { return pnf(f, true); }

}  // namespace physltl::ltl
