#include "physltl/ltl/lasso.h"

#include <algorithm>
#include <stdexcept>

namespace physltl::ltl {
namespace {

using Truth = std::vector<char>;  // per position

class LassoWord {
 public:
  LassoWord(std::span<const std::vector<std::string>> letters, std::size_t loop_start)
      : letters_(letters), loop_start_(loop_start) {
    if (letters.empty() || loop_start >= letters.size()) {
      throw std::invalid_argument("holds_on_lasso: the loop must start at a position of a non-empty word");
    }
  }

  std::size_t size() const { return letters_.size(); }
  std::size_t next(std::size_t i) const { return i + 1 < letters_.size() ? i + 1 : loop_start_; }

  // The truth of f at every position.
  Truth eval(const Formula& f) const {
    const std::size_t n = size();
    Truth out(n, 0);
    switch (f.op()) {
      case Op::True: std::ranges::fill(out, 1); break;
      case Op::False: break;
      case Op::Atom:
        for (std::size_t i = 0; i < n; ++i) out[i] = std::ranges::find(letters_[i], f.name()) != letters_[i].end();
        break;
      case Op::Not: {
        const Truth a = eval(f.child(0));
        for (std::size_t i = 0; i < n; ++i) out[i] = !a[i];
        break;
      }
      case Op::And:
      case Op::Or: {
        const bool conjunction = f.op() == Op::And;
        std::ranges::fill(out, conjunction ? 1 : 0);
        for (const Formula& c : f.children()) {
          const Truth a = eval(c);
          for (std::size_t i = 0; i < n; ++i) out[i] = conjunction ? (out[i] && a[i]) : (out[i] || a[i]);
        }
        break;
      }
      case Op::Implies:
      case Op::Equiv:
      case Op::Xor: {
        const Truth a = eval(f.child(0)), b = eval(f.child(1));
        for (std::size_t i = 0; i < n; ++i) {
          out[i] = f.op() == Op::Implies ? (!a[i] || b[i]) : f.op() == Op::Equiv ? (a[i] == b[i]) : (a[i] != b[i]);
        }
        break;
      }
      case Op::Next: {
        const Truth a = eval(f.child(0));
        for (std::size_t i = 0; i < n; ++i) out[i] = a[next(i)];
        break;
      }
      // a U b = b | (a & X(a U b)), the least solution; a R b = b & (a | X(a R b)), the greatest.
      case Op::Finally: return fixpoint(Truth(n, 1), eval(f.child(0)), false);
      case Op::Globally: return fixpoint(eval(f.child(0)), Truth(n, 0), true);
      case Op::Until: return fixpoint(eval(f.child(0)), eval(f.child(1)), false);
      case Op::WeakUntil: return fixpoint(eval(f.child(0)), eval(f.child(1)), true);
      case Op::Release: return fixpoint(eval(f.child(0)), eval(f.child(1)), true, false);
      case Op::StrongRelease: return fixpoint(eval(f.child(0)), eval(f.child(1)), false, false);
    }
    return out;
  }

 private:
  // x = b | (a & X x) (`until`), or x = b & (a | X x): the least solution from all false (U, F, M), the
  // greatest from all true (W, G, R). Sweeps backwards until nothing changes; each sweep settles at least
  // one more position of the loop.
  Truth fixpoint(const Truth& a, const Truth& b, bool greatest, bool until = true) const {
    const std::size_t n = size();
    Truth x(n, greatest ? 1 : 0);
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t k = n; k-- > 0;) {
        const char value = until ? (b[k] || (a[k] && x[next(k)])) : (b[k] && (a[k] || x[next(k)]));
        changed |= value != x[k];
        x[k] = value;
      }
    }
    return x;
  }

  std::span<const std::vector<std::string>> letters_;
  std::size_t loop_start_;
};

}  // namespace

bool holds_on_lasso(const Formula& f, std::span<const std::vector<std::string>> letters, std::size_t loop_start) {
  return LassoWord(letters, loop_start).eval(f)[0];
}

bool holds_when_staying(const Formula& f, std::span<const std::vector<std::string>> trace) {
  if (trace.empty()) throw std::invalid_argument("holds_when_staying: a run has at least its first state");
  return holds_on_lasso(f, trace, trace.size() - 1);
}

}  // namespace physltl::ltl
