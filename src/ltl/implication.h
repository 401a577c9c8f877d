#pragma once
// Private to the ltl module: whether one formula in positive normal form implies another, decided from
// their syntax alone (the rules of Somenzi and Bloem, "Efficient Buchi automata from LTL formulae", CAV
// 2000, table 1, as Spot applies them). Sound, not complete: `true` means every word satisfying `f`
// satisfies `g`; `false` means the rules could not show it. The translation uses it to drop the parts
// of a state that another part already implies: in `a1 U (a2 U (a3 U ...))` every later stage implies
// the earlier ones, and without it each set of stages reached at once was a state of its own (2^n before
// minimising, for an automaton of n + 1).

#include "physltl/ltl/formula.h"

#include <unordered_map>
#include <utility>

namespace physltl::ltl::detail {

class Implication {
 public:
  bool operator()(const Formula& f, const Formula& g);

 private:
  bool decide(const Formula& f, const Formula& g);

  struct PairHash {
    std::size_t operator()(const std::pair<Formula, Formula>& p) const {
      return p.first.hash() * 0x9E3779B97F4A7C15ULL ^ p.second.hash();
    }
  };
  std::unordered_map<std::pair<Formula, Formula>, bool, PairHash> memo_;
};

}  // namespace physltl::ltl::detail
