#include "physltl/ltl/progression.h"

#include <algorithm>

namespace physltl::ltl {
namespace {

Formula negate(const Formula& f) {
  if (f.op() == Op::True) return Formula::ff();
  if (f.op() == Op::False) return Formula::tt();
  if (f.op() == Op::Not) return f.child(0);
  return Formula::unary(Op::Not, f);
}

// And/Or without constants and without an operand twice; flattened, as Formula::nary flattens.
Formula junction(Op op, const std::vector<Formula>& operands) {
  const Op absorbing = op == Op::And ? Op::False : Op::True;
  const Op neutral = op == Op::And ? Op::True : Op::False;
  std::vector<Formula> kept;
  for (const auto& operand : operands) {
    std::vector<Formula> parts;
    if (operand.op() == op) {
      parts.assign(operand.children().begin(), operand.children().end());
    } else {
      parts.push_back(operand);
    }
    for (const auto& part : parts) {
      if (part.op() == absorbing) return part;
      if (part.op() == neutral || std::find(kept.begin(), kept.end(), part) != kept.end()) continue;
      kept.push_back(part);
    }
  }
  if (kept.empty()) return op == Op::And ? Formula::tt() : Formula::ff();
  if (kept.size() == 1) return kept.front();
  return Formula::nary(op, std::move(kept));
}

Formula both(const Formula& a, const Formula& b) { return junction(Op::And, {a, b}); }
Formula either(const Formula& a, const Formula& b) { return junction(Op::Or, {a, b}); }

}  // namespace

Formula progress(const Formula& f, const std::vector<std::string>& letter) {
  const auto now = [&](const Formula& g) { return progress(g, letter); };
  switch (f.op()) {
    case Op::True:
    case Op::False: return f;
    case Op::Atom:
      return std::find(letter.begin(), letter.end(), f.name()) != letter.end() ? Formula::tt() : Formula::ff();
    case Op::Not: return negate(now(f.child(0)));
    case Op::Next: return f.child(0);
    case Op::Finally: return either(now(f.child(0)), f);
    case Op::Globally: return both(now(f.child(0)), f);
    case Op::And:
    case Op::Or: {
      std::vector<Formula> operands;
      for (const auto& child : f.children()) operands.push_back(now(child));
      return junction(f.op(), operands);
    }
    case Op::Implies: return either(negate(now(f.child(0))), now(f.child(1)));
    case Op::Equiv:
    case Op::Xor: {
      const Formula a = now(f.child(0)), b = now(f.child(1));
      const Formula same = either(both(a, b), both(negate(a), negate(b)));
      return f.op() == Op::Equiv ? same : negate(same);
    }
    // a U b: b now, or a now and a U b from the next letter; W the same, M and R their duals.
    case Op::Until:
    case Op::WeakUntil: return either(now(f.child(1)), both(now(f.child(0)), f));
    case Op::Release:
    case Op::StrongRelease: return both(now(f.child(1)), either(now(f.child(0)), f));
  }
  return f;
}

}  // namespace physltl::ltl
