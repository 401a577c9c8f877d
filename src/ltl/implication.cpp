#include "implication.h"

#include <algorithm>

namespace physltl::ltl::detail {

bool Implication::operator()(const Formula& f, const Formula& g) {
  if (g.op() == Op::True || f.op() == Op::False || f == g) return true;
  const auto key = std::make_pair(f, g);
  if (auto it = memo_.find(key); it != memo_.end()) return it->second;
  const bool result = decide(f, g);
  memo_.emplace(key, result);
  return result;
}

// Each rule names a fact of LTL on every word and position; f and g are read at the same position.
bool Implication::decide(const Formula& f, const Formula& g) {
  Implication& implies = *this;
  const auto f_children = f.children();
  const auto g_children = g.children();
  const auto any_child_of_g = [&] {
    return std::ranges::any_of(g_children, [&](const Formula& c) { return implies(f, c); });
  };
  const auto both_operands_imply = [&](const Formula& a, const Formula& b) {  // f's a and b, g's same operator
    return implies(f.child(0), a) && implies(f.child(1), b);
  };
  // What g is: f implies it if it implies the part g cannot do without.
  switch (g.op()) {
    case Op::And:
      if (std::ranges::all_of(g_children, [&](const Formula& c) { return implies(f, c); })) return true;
      break;
    case Op::Or:
      if (any_child_of_g()) return true;
      break;
    case Op::Finally:  // b -> F b; F a -> F b when a -> F b (F F b = F b); a U c -> F b when c -> F b
      if (implies(f, g.child(0))) return true;
      if ((f.op() == Op::Finally && implies(f.child(0), g)) || (f.op() == Op::Until && implies(f.child(1), g))) return true;
      break;
    case Op::Until:  // b -> a U b; a U b -> c U d when a -> c and b -> d
    case Op::WeakUntil:
      if (implies(f, g.child(1))) return true;
      if ((f.op() == Op::Until || (g.op() == Op::WeakUntil && f.op() == Op::WeakUntil)) &&
          both_operands_imply(g.child(0), g.child(1)))
        return true;
      if (g.op() == Op::WeakUntil && f.op() == Op::Globally && implies(f.child(0), g.child(0))) return true;  // G a -> a W b
      break;
    case Op::StrongRelease:  // a & b -> a M b
    case Op::Release:
      if (implies(f, g.child(0)) && implies(f, g.child(1))) return true;
      if ((f.op() == Op::StrongRelease || (g.op() == Op::Release && f.op() == Op::Release)) &&
          both_operands_imply(g.child(0), g.child(1)))
        return true;
      if (g.op() == Op::Release && f.op() == Op::Globally && implies(f.child(0), g.child(1))) return true;  // G b -> a R b
      break;
    case Op::Globally:  // G a -> G b when a -> b
      if (f.op() == Op::Globally && implies(f.child(0), g.child(0))) return true;
      break;
    case Op::Next:  // X a -> X b when a -> b; G a -> X b when a -> b
      if ((f.op() == Op::Next || f.op() == Op::Globally) && implies(f.child(0), g.child(0))) return true;
      break;
    default: break;
  }
  // What f is: it implies g if what f must hold now does.
  switch (f.op()) {
    case Op::Or: return std::ranges::all_of(f_children, [&](const Formula& c) { return implies(c, g); });
    case Op::And: return std::ranges::any_of(f_children, [&](const Formula& c) { return implies(c, g); });
    case Op::Until:      // a U b holds b now or a now
    case Op::WeakUntil:  // a W b the same
      return implies(f.child(0), g) && implies(f.child(1), g);
    case Op::StrongRelease:  // a M b and a R b hold b now
    case Op::Release: return implies(f.child(1), g);
    case Op::Globally: return implies(f.child(0), g);  // G a holds a now
    default: return false;
  }
}

}  // namespace physltl::ltl::detail
