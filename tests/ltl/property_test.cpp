// The automaton against an independent reference, on random co-safe formulas and random traces.
//
// The reference shares no code with the translator beyond the Formula type:
//  * progression of a formula over one letter, on formula trees, with its own normalisation;
//  * "is the residual valid" decided on the graph of residuals by a naive fixpoint;
//  * the verdicts confirmed by direct LTL semantics on ultimately periodic words (lassos): a rejected
//    trace gets a concrete counterexample continuation, an accepted one is tried on random ones.
// It also minimises the residual graph over explicit letters to check the automaton's size is minimal,
// and holds the syntactic implication the translation simplifies its states with to the same semantics.

#include "implication.h"
#include "physltl/ltl/lasso.h"
#include "physltl/ltl/progression.h"
#include "physltl/ltl/translate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <map>
#include <random>
#include <unordered_map>

namespace physltl::ltl {
namespace {

constexpr int kProps = 3;  // a, b, c; a letter is a bit mask
constexpr int kLetters = 1 << kProps;
const char* const kNames[kProps] = {"a", "b", "c"};

// ---- random formulas in positive normal form: co-safe ones, and any (with G, R, W too) ----

Formula random_formula(std::mt19937_64& rng, int depth, bool full_ltl = false) {
  std::uniform_int_distribution<int> pick(0, 99);
  if (depth == 0 || pick(rng) < 25) {
    const int r = pick(rng);
    if (r < 6) return Formula::tt();
    if (r < 10) return Formula::ff();
    Formula atom = Formula::atom(kNames[r % kProps]);
    return r % 2 ? atom : Formula::unary(Op::Not, atom);
  }
  const int r = pick(rng);
  auto sub = [&] { return random_formula(rng, depth - 1, full_ltl); };
  if (full_ltl && r >= 70) {
    const int kind = r % 3;
    if (kind == 0) return Formula::unary(Op::Globally, sub());
    if (kind == 1) return Formula::binary(Op::Release, sub(), sub());
    return Formula::binary(Op::WeakUntil, sub(), sub());
  }
  if (r < 18) return Formula::nary(Op::And, {sub(), sub()});
  if (r < 36) return Formula::nary(Op::Or, {sub(), sub()});
  if (r < 52) return Formula::unary(Op::Next, sub());
  if (r < 70) return Formula::unary(Op::Finally, sub());
  if (r < 88) return Formula::binary(Op::Until, sub(), sub());
  return Formula::binary(Op::StrongRelease, sub(), sub());
}

// ---- the reference: progression with its own normalisation ----

Formula junction(Op op, const std::vector<Formula>& operands) {
  const Op unit = op == Op::And ? Op::True : Op::False;
  std::vector<Formula> flat;
  for (const Formula& f : operands) {
    if (f.op() == unit) continue;
    if (f.is_constant()) return f;  // the absorbing constant
    if (f.op() == op)
      flat.insert(flat.end(), f.children().begin(), f.children().end());
    else
      flat.push_back(f);
  }
  std::sort(flat.begin(), flat.end());
  flat.erase(std::unique(flat.begin(), flat.end()), flat.end());
  return Formula::nary(op, std::move(flat));
}

Formula progress(const Formula& f, int letter) {
  auto holds = [&](const Formula& atom) {
    return (letter >> (std::find(kNames, kNames + kProps, atom.name()) - kNames)) & 1;
  };
  switch (f.op()) {
    case Op::True:
    case Op::False: return f;
    case Op::Atom: return holds(f) ? Formula::tt() : Formula::ff();
    case Op::Not: return holds(f.child(0)) ? Formula::ff() : Formula::tt();
    case Op::And:
    case Op::Or: {
      std::vector<Formula> parts;
      for (const Formula& c : f.children()) parts.push_back(progress(c, letter));
      return junction(f.op(), parts);
    }
    case Op::Next: return f.child(0);
    case Op::Finally: return junction(Op::Or, {progress(f.child(0), letter), f});
    case Op::Until:
      return junction(Op::Or, {progress(f.child(1), letter), junction(Op::And, {progress(f.child(0), letter), f})});
    case Op::StrongRelease:
    case Op::Release:
      return junction(Op::And, {progress(f.child(1), letter), junction(Op::Or, {progress(f.child(0), letter), f})});
    case Op::Globally: return junction(Op::And, {progress(f.child(0), letter), f});
    case Op::WeakUntil:
      return junction(Op::Or, {progress(f.child(1), letter), junction(Op::And, {progress(f.child(0), letter), f})});
    default: throw std::logic_error("operator not generated");
  }
}

// Residuals are compared as Boolean functions of their temporal atoms (the maximal subformulas that
// are not & | true false): sorted essential atoms plus a truth table. Without such a canonical form,
// progression can produce ever deeper but equivalent formulas.
std::string canonical_key(const Formula& f) {
  std::vector<Formula> atoms;
  auto collect = [&](auto& self, const Formula& g) -> void {
    if (g.op() == Op::And || g.op() == Op::Or) {
      for (const Formula& c : g.children()) self(self, c);
    } else if (!g.is_constant()) {
      atoms.push_back(g);
    }
  };
  collect(collect, f);
  std::sort(atoms.begin(), atoms.end());
  atoms.erase(std::unique(atoms.begin(), atoms.end()), atoms.end());
  if (atoms.size() > 16) throw std::runtime_error("reference: residual too large: " + to_string(f));
  auto eval = [&](auto& self, const Formula& g, unsigned assignment) -> bool {
    switch (g.op()) {
      case Op::True: return true;
      case Op::False: return false;
      case Op::And: return std::ranges::all_of(g.children(), [&](const Formula& c) { return self(self, c, assignment); });
      case Op::Or: return std::ranges::any_of(g.children(), [&](const Formula& c) { return self(self, c, assignment); });
      default: return (assignment >> (std::lower_bound(atoms.begin(), atoms.end(), g) - atoms.begin())) & 1;
    }
  };
  const unsigned rows = 1u << atoms.size();
  std::vector<bool> table(rows);
  for (unsigned a = 0; a < rows; ++a) table[a] = eval(eval, f, a);
  // Project the table onto the essential atoms so that equal functions get equal keys.
  std::string essential_key;
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    bool essential = false;
    for (unsigned a = 0; a < rows && !essential; ++a) essential = table[a] != table[a ^ (1u << i)];
    if (essential) {
      kept.push_back(i);
      essential_key += to_string(atoms[i]) + ";";
    }
  }
  essential_key += '|';
  for (unsigned r = 0; r < (1u << kept.size()); ++r) {
    unsigned a = 0;
    for (std::size_t k = 0; k < kept.size(); ++k) a |= ((r >> k) & 1u) << kept[k];
    essential_key += table[a] ? '1' : '0';
  }
  return essential_key;
}

// The number of states of the minimal automaton: Moore refinement over explicit letters, from the classes
// "accepting" (1) and not (0).
std::size_t moore_size(std::vector<int> cls, const std::vector<std::array<int, kLetters>>& next) {
  std::size_t count = 0;
  while (true) {
    std::map<std::vector<int>, int> ids;
    std::vector<int> next_cls(cls.size());
    for (std::size_t i = 0; i < cls.size(); ++i) {
      std::vector<int> sig{cls[i]};
      for (int t : next[i]) sig.push_back(cls[t]);
      next_cls[i] = ids.try_emplace(sig, static_cast<int>(ids.size())).first->second;
    }
    cls = next_cls;
    if (ids.size() == count) return count;
    count = ids.size();
  }
}

// The residual graph of a formula over explicit letters, with good = "valid on every infinite word".
struct Reference {
  std::vector<Formula> nodes;
  std::vector<std::array<int, kLetters>> next;
  std::vector<std::string> keys;
  std::vector<bool> good;
  static constexpr const char* kTrueKey = "|1";  // no essential atom, and true

  explicit Reference(const Formula& f) {
    std::unordered_map<std::string, int> index;
    auto id = [&](const Formula& g) {
      std::string key = canonical_key(g);
      auto [it, inserted] = index.try_emplace(key, static_cast<int>(nodes.size()));
      if (inserted) {
        nodes.push_back(g);
        keys.push_back(std::move(key));
      }
      return it->second;
    };
    id(f);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (nodes.size() > 20000) throw std::runtime_error("reference did not converge for " + to_string(f));
      std::array<int, kLetters> succ{};
      for (int l = 0; l < kLetters; ++l) succ[l] = id(progress(nodes[i], l));
      next.push_back(succ);
    }
    // A co-safe formula holds on a word iff some prefix progresses it to true; so a residual is valid
    // iff every path from it reaches true. Naive sweeps until nothing changes.
    good.assign(nodes.size(), false);
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (good[i]) continue;
        const bool now = keys[i] == kTrueKey ||
                         std::ranges::all_of(next[i], [&](int j) { return static_cast<bool>(good[j]); });
        if (now) good[i] = changed = true;
      }
    }
  }
  int run(const std::vector<int>& trace) const {
    int s = 0;
    for (int l : trace) s = next[s][l];
    return s;
  }

  // A continuation that never becomes good, from a node that is not: it exists by definition.
  std::pair<std::vector<int>, std::size_t> counterexample(int from) const {
    std::vector<int> letters;
    std::vector<int> visited{from};
    int s = from;
    while (true) {
      const int l = static_cast<int>(std::ranges::find_if(next[s], [&](int t) { return !good[t]; }) - next[s].begin());
      letters.push_back(l);
      s = next[s][l];
      if (auto it = std::ranges::find(visited, s); it != visited.end())
        return {letters, static_cast<std::size_t>(it - visited.begin())};  // loop back to that position
      visited.push_back(s);
    }
  }

  std::size_t minimal_size() const { return moore_size(std::vector<int>(good.begin(), good.end()), next); }
};

// ---- direct LTL semantics on the lasso word u v^omega ----

struct Lasso {
  std::vector<int> letters;  // u followed by v
  std::size_t loop;          // index where v starts
  std::size_t succ(std::size_t i) const { return i + 1 < letters.size() ? i + 1 : loop; }
};

std::vector<bool> satisfied(const Formula& f, const Lasso& w) {
  const std::size_t n = w.letters.size();
  std::vector<bool> out(n);
  auto atom_at = [&](const Formula& a, std::size_t i) {
    return static_cast<bool>((w.letters[i] >> (std::find(kNames, kNames + kProps, a.name()) - kNames)) & 1);
  };
  std::vector<std::vector<bool>> kids;
  for (const Formula& c : f.children()) kids.push_back(f.op() == Op::Not ? std::vector<bool>{} : satisfied(c, w));
  for (std::size_t i = 0; i < n; ++i) {
    switch (f.op()) {
      case Op::True: out[i] = true; break;
      case Op::False: out[i] = false; break;
      case Op::Atom: out[i] = atom_at(f, i); break;
      case Op::Not: out[i] = !atom_at(f.child(0), i); break;
      case Op::And: out[i] = std::ranges::all_of(kids, [&](const auto& k) { return static_cast<bool>(k[i]); }); break;
      case Op::Or: out[i] = std::ranges::any_of(kids, [&](const auto& k) { return static_cast<bool>(k[i]); }); break;
      case Op::Next: out[i] = kids[0][w.succ(i)]; break;
      case Op::Globally:
      case Op::Release:
      case Op::WeakUntil: {
        // The dual walk: the position is good unless the walk meets a failure first.
        const std::vector<bool>& left = kids[0];
        const std::vector<bool>& right = f.op() == Op::Globally ? kids[0] : kids[1];
        bool result = true;
        std::size_t p = i;
        for (std::size_t k = 0; k <= n; ++k, p = w.succ(p)) {
          if (f.op() == Op::Globally) {
            if (!left[p]) { result = false; break; }
          } else if (f.op() == Op::Release) {  // b holds up to and including a position where a holds, or forever
            if (!right[p]) { result = false; break; }
            if (left[p]) break;
          } else {  // a W b: a holds until b, or forever
            if (right[p]) break;
            if (!left[p]) { result = false; break; }
          }
        }
        out[i] = result;
        break;
      }
      case Op::Finally:
      case Op::Until:
      case Op::StrongRelease: {
        // Walk forward; after n steps every position of the lasso reachable from i has been seen.
        const std::vector<bool>& left = f.op() == Op::Finally ? kids[0] : kids[0];
        const std::vector<bool>& right = f.op() == Op::Finally ? kids[0] : kids[1];
        bool result = false;
        std::size_t p = i;
        for (std::size_t k = 0; k <= n; ++k, p = w.succ(p)) {
          if (f.op() == Op::Finally) {
            if (right[p]) { result = true; break; }
          } else if (f.op() == Op::Until) {
            if (right[p]) { result = true; break; }
            if (!left[p]) break;
          } else {  // a M b: b holds up to and including a position where a holds too
            if (!right[p]) break;
            if (left[p]) { result = true; break; }
          }
        }
        out[i] = result;
        break;
      }
      default: throw std::logic_error("operator not generated");
    }
  }
  return out;
}

bool holds(const Formula& f, const std::vector<int>& prefix, const std::vector<int>& tail, std::size_t loop) {
  Lasso w{prefix, prefix.size() + loop};
  w.letters.insert(w.letters.end(), tail.begin(), tail.end());
  return satisfied(f, w)[0];
}

// ---- the property ----

bool dfa_accepts(const Dfa& dfa, const std::vector<int>& trace) {
  std::vector<int> index(kProps);
  for (int p = 0; p < kProps; ++p) index[p] = dfa.proposition_index(kNames[p]);
  int s = dfa.start;
  bool truth[kProps] = {};
  for (int letter : trace) {
    for (int p = 0; p < kProps; ++p)
      if (index[p] >= 0) truth[index[p]] = (letter >> p) & 1;
    s = dfa.step_by_truth(s, std::span<const bool>(truth, dfa.propositions.size()));
  }
  return dfa.accepting[s];
}

TEST(TranslateProperty, AcceptsExactlyTheGoodPrefixesOfRandomCoSafeFormulas) {
  std::mt19937_64 rng(20170709);
  std::uniform_int_distribution<int> letter(0, kLetters - 1);
  std::uniform_int_distribution<int> length(0, 10);
  constexpr int kFormulas = 400;
  constexpr int kTraces = 2000;
  int accepted = 0;
  int rejected = 0;
  for (int i = 0; i < kFormulas; ++i) {
    const Formula f = random_formula(rng, 4);
    SCOPED_TRACE(to_string(f));
    const Dfa dfa = translate(f);
    const Reference ref(f);
    ASSERT_EQ(dfa.size(), ref.minimal_size());
    for (int t = 0; t < kTraces; ++t) {
      std::vector<int> trace(static_cast<std::size_t>(length(rng)));
      for (int& l : trace) l = letter(rng);
      const int residual = ref.run(trace);
      const bool good = ref.good[residual];
      ASSERT_EQ(dfa_accepts(dfa, trace), good) << "trace of length " << trace.size();
      (good ? accepted : rejected) += 1;
      if (t % 20 != 0) continue;  // confirm the reference by direct semantics on a sample
      if (good) {
        for (int k = 0; k < 3; ++k) {
          std::vector<int> tail(static_cast<std::size_t>(1 + length(rng) % 4));
          for (int& l : tail) l = letter(rng);
          ASSERT_TRUE(holds(f, trace, tail, static_cast<std::size_t>(length(rng)) % tail.size()));
        }
      } else {
        const auto [tail, loop] = ref.counterexample(residual);
        ASSERT_FALSE(holds(f, trace, tail, loop));
      }
    }
  }
  // Both verdicts occur often enough for the comparison to mean something.
  EXPECT_GT(accepted, kFormulas * kTraces / 10);
  EXPECT_GT(rejected, kFormulas * kTraces / 10);
}

// ---- stop and stay: tasks that are not co-safe ----

// The minimal size of the stop-and-stay automaton, by explicit Moore refinement over the reference's
// residuals paired with "the run stopping here satisfies the task" (the residual before the last letter
// evaluated on that letter repeated forever).
std::size_t minimal_stop_and_stay_size(const Formula& f) {
  std::vector<std::string> keys;
  std::vector<Formula> residuals;
  std::unordered_map<std::string, int> index;
  auto residual_id = [&](const Formula& g) {
    std::string key = canonical_key(g);
    auto [it, inserted] = index.try_emplace(key, static_cast<int>(residuals.size()));
    if (inserted) residuals.push_back(g);
    return it->second;
  };
  std::map<std::pair<int, bool>, int> state_of;
  std::vector<std::pair<int, bool>> states;
  std::vector<std::array<int, kLetters>> next;
  auto state_id = [&](std::pair<int, bool> s) {
    auto [it, inserted] = state_of.try_emplace(s, static_cast<int>(states.size()));
    if (inserted) states.push_back(s);
    return it->second;
  };
  state_id({residual_id(f), false});
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (states.size() > 20000) throw std::runtime_error("reference did not converge for " + to_string(f));
    std::array<int, kLetters> succ{};
    for (int l = 0; l < kLetters; ++l) {
      const Formula& r = residuals[static_cast<std::size_t>(states[i].first)];
      const bool stays = holds(r, {}, {l}, 0);
      succ[l] = state_id({residual_id(progress(r, l)), stays});
    }
    next.push_back(succ);
  }
  std::vector<int> accepting(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) accepting[i] = states[i].second;
  return moore_size(std::move(accepting), next);
}

// Regions are disjoint: a letter has at most one proposition.
constexpr int kRegionLetters[] = {0, 1, 2, 4};

TEST(TranslateProperty, AcceptsExactlyTheRunsThatSatisfyRandomFormulasWhenTheRobotStopsAndStays) {
  std::mt19937_64 rng(20261201);
  std::uniform_int_distribution<int> letter(0, 3);
  std::uniform_int_distribution<int> length(1, 10);
  constexpr int kFormulas = 300;
  constexpr int kTraces = 2000;
  int stop_and_stay = 0, accepted = 0, rejected = 0;
  for (int i = 0; i < kFormulas; ++i) {
    const Formula f = random_formula(rng, 4, true);
    SCOPED_TRACE(to_string(f));
    const Dfa dfa = translate(f);
    if (dfa.acceptance != Acceptance::kStopAndStay) continue;  // co-safe: the test above
    ++stop_and_stay;
    ASSERT_EQ(dfa.size(), minimal_stop_and_stay_size(f));
    for (int t = 0; t < kTraces; ++t) {
      std::vector<int> trace(static_cast<std::size_t>(length(rng)));
      for (int& l : trace) l = kRegionLetters[letter(rng)];
      const std::vector<int> prefix(trace.begin(), trace.end() - 1);
      const bool expected = holds(f, prefix, {trace.back()}, 0);  // the last letter forever
      ASSERT_EQ(dfa_accepts(dfa, trace), expected) << "trace of length " << trace.size();
      (expected ? accepted : rejected) += 1;
      if (t % 10 != 0) continue;  // the evaluator replay uses, against this one
      std::vector<std::vector<std::string>> named;
      for (int l : trace) named.push_back(l == 0 ? std::vector<std::string>{} : std::vector<std::string>{kNames[std::countr_zero(static_cast<unsigned>(l))]});
      ASSERT_EQ(holds_when_staying(f, named), expected);
    }
  }
  EXPECT_GT(stop_and_stay, kFormulas / 3);
  EXPECT_GT(accepted, stop_and_stay * kTraces / 10);
  EXPECT_GT(rejected, stop_and_stay * kTraces / 10);
}

// The translation drops the parts of a state another part implies (implication.h): every implication it
// takes must hold at every position of every word. Pairs are built so that many hold (g from f by an
// operator that weakens it) and many nearly do (the other way round, or a random partner).
TEST(ImplicationProperty, WhatTheTranslationTakesAsImpliedHoldsAtEveryPositionOfRandomWords) {
  std::mt19937_64 rng(20261206);
  std::uniform_int_distribution<int> letter(0, kLetters - 1), length(1, 5), kind(0, 6);
  detail::Implication implies;
  int claims = 0, beyond_equality = 0;
  for (int i = 0; i < 4000; ++i) {
    const Formula f = random_formula(rng, 3, true);
    const Formula h = random_formula(rng, 2, true);
    const auto weakened = [&](int how) {
      switch (how) {
        case 0: return random_formula(rng, 3, true);
        case 1: return Formula::unary(Op::Finally, f);
        case 2: return Formula::binary(Op::Until, h, f);
        case 3: return Formula::nary(Op::Or, {f, h});
        case 4: return Formula::binary(Op::WeakUntil, h, f);
        case 5: return Formula::binary(Op::Release, h, f);
        default: return Formula::unary(Op::Finally, Formula::nary(Op::And, {h, f}));
      }
    };
    const Formula g = weakened(kind(rng));
    for (const auto& [x, y] : {std::pair{f, g}, std::pair{g, f}}) {
      if (!implies(x, y)) continue;
      ++claims;
      beyond_equality += x != y && y.op() != Op::True && x.op() != Op::False;
      for (int w = 0; w < 40; ++w) {
        Lasso word{{}, static_cast<std::size_t>(length(rng) - 1)};
        word.letters.resize(word.loop + static_cast<std::size_t>(length(rng)));
        for (int& l : word.letters) l = letter(rng);
        const std::vector<bool> sx = satisfied(x, word), sy = satisfied(y, word);
        for (std::size_t p = 0; p < sx.size(); ++p) {
          ASSERT_TRUE(!sx[p] || sy[p]) << to_string(x) << " was taken to imply " << to_string(y) << " (position " << p << ")";
        }
      }
    }
  }
  EXPECT_GT(beyond_equality, 2000) << "of " << claims;
}

// For co-safe tasks the two readings agree when the formula has no X: a good prefix, with its last
// letter repeated, satisfies the formula (stutter invariance gives the converse for the first good prefix).
TEST(TranslateProperty, AGoodPrefixAlsoSatisfiesTheTaskWhenTheRobotStopsAndStays) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> letter(0, 3);
  std::uniform_int_distribution<int> length(1, 8);
  for (int i = 0; i < 200; ++i) {
    const Formula f = random_formula(rng, 3);
    const Dfa dfa = translate(f);
    for (int t = 0; t < 200; ++t) {
      std::vector<int> trace(static_cast<std::size_t>(length(rng)));
      for (int& l : trace) l = kRegionLetters[letter(rng)];
      if (!dfa_accepts(dfa, trace)) continue;
      const std::vector<int> prefix(trace.begin(), trace.end() - 1);
      ASSERT_TRUE(holds(f, prefix, {trace.back()}, 0)) << to_string(f);
    }
  }
}

// Execution hands the planner the task progressed over the letters executed so far: a trace satisfies f
// exactly when its rest satisfies f progressed over its first letter, and however long the trace the
// progressed formula stays small.
TEST(ProgressionProperty, ATraceSatisfiesTheFormulaExactlyWhenItsRestSatisfiesTheProgressedOne) {
  std::mt19937_64 rng(20261202);
  std::uniform_int_distribution<int> letter(0, 3);
  std::uniform_int_distribution<int> length(2, 10);
  int checked = 0, satisfied = 0;
  for (int i = 0; i < 300; ++i) {
    const Formula f = random_formula(rng, 4, true);
    SCOPED_TRACE(to_string(f));
    for (int t = 0; t < 200; ++t) {
      std::vector<std::vector<std::string>> trace(static_cast<std::size_t>(length(rng)));
      for (auto& l : trace) {
        const int bits = kRegionLetters[letter(rng)];
        if (bits != 0) l.push_back(kNames[std::countr_zero(static_cast<unsigned>(bits))]);
      }
      const bool whole = holds_when_staying(f, trace);
      Formula rest = f;
      for (size_t k = 0; k + 1 < trace.size(); ++k) {
        rest = progress(rest, trace[k]);
        const std::vector<std::vector<std::string>> after(trace.begin() + static_cast<long>(k) + 1, trace.end());
        ASSERT_EQ(holds_when_staying(rest, after), whole) << "after " << k + 1 << " letters: " << to_string(rest);
      }
      ++checked;
      satisfied += whole;
    }
    Formula long_run = f;
    for (int k = 0; k < 500; ++k) {
      const int bits = kRegionLetters[letter(rng)];
      long_run = progress(long_run, bits == 0 ? std::vector<std::string>{}
                                              : std::vector<std::string>{kNames[std::countr_zero(static_cast<unsigned>(bits))]});
    }
    EXPECT_LT(to_string(long_run).size(), 40 * to_string(f).size() + 40);
  }
  EXPECT_GT(satisfied, checked / 10);
  EXPECT_LT(satisfied, checked * 9 / 10);
}

}  // namespace
}  // namespace physltl::ltl
