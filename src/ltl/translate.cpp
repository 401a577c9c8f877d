#include "physltl/ltl/translate.h"

#include "decision_diagram.h"
#include "implication.h"
#include "normal_form.h"
#include "physltl/ltl/task_class.h"

#include <algorithm>
#include <deque>
#include <iterator>
#include <optional>
#include <map>
#include <unordered_map>

namespace physltl::ltl {

namespace {

using detail::DecisionDiagram;
using Node = DecisionDiagram::Node;

// A state of the progression automaton is a positive Boolean combination of "atoms" (literals and the
// temporal subformulas X, F, U, M), kept as a DNF: a set of terms, each a sorted set of atom ids, no term
// implying another and no atom of a term implied by another of it (implication.h). Finitely many exist;
// equal states are found by comparing DNFs, and the few equivalent ones that differ are merged when
// minimising.
using Term = std::vector<int>;
using Dnf = std::vector<Term>;

struct VectorHash {
  std::size_t operator()(const Term& t) const {
    std::size_t h = t.size();
    for (int x : t) h = h * 0x100000001B3ULL ^ static_cast<std::size_t>(x);
    return h;
  }
  std::size_t operator()(const Dnf& d) const {
    std::size_t h = d.size();
    for (const Term& t : d) h = h * 0x9E3779B97F4A7C15ULL ^ (*this)(t);
    return h;
  }
};

constexpr int kFalse = 0;  // DNF ids of the constants
constexpr int kTrue = 1;

// A state of the automaton before minimisation is a key: for good-prefix acceptance the DNF id of the
// formula still to satisfy; for stop-and-stay acceptance twice that id plus one bit, whether the run
// read so far satisfies the task if it stops and stays (the formula before the last letter, evaluated on
// that letter repeated forever: what progression reads next is all that letter).
class Translator {
 public:
  Translator(std::vector<std::string> props, Acceptance acceptance)
      : props_(std::move(props)), stop_and_stay_(acceptance == Acceptance::kStopAndStay) {
    intern_dnf(Dnf{});        // kFalse: no term
    intern_dnf(Dnf{Term{}});  // kTrue: the empty term
  }

  Dfa run(const Formula& pnf) {
    const int formula = dnf_of(pnf);
    explore(stop_and_stay_ ? 2 * formula : formula);  // the empty run does not stop anywhere: not accepting
    std::vector<bool> accepting;
    if (stop_and_stay_) {
      for (int key : state_keys_) accepting.push_back(key % 2 == 1);
    } else {
      accepting = good_states();
    }
    Dfa dfa = minimise(accepting);
    dfa.acceptance = stop_and_stay_ ? Acceptance::kStopAndStay : Acceptance::kGoodPrefix;
    return dfa;
  }

 private:
  // ---- atoms and DNFs ----

  bool atom_implies(int x, int y) {
    if (x == y) return true;
    auto& row = atom_implies_[static_cast<std::size_t>(x)];
    if (row.size() <= static_cast<std::size_t>(y)) row.resize(atoms_.size(), kUnknown);
    signed char& known = row[static_cast<std::size_t>(y)];
    if (known == kUnknown) known = implies_(atoms_[x], atoms_[y]) ? 1 : 0;
    return known == 1;
  }

  // Every atom of `b` implied by one of `a`: the conjunction `a` implies `b`.
  bool term_implies(const Term& a, const Term& b) {
    if (std::ranges::includes(a, b)) return true;
    return std::ranges::all_of(b, [&](int y) { return std::ranges::any_of(a, [&](int x) { return atom_implies(x, y); }); });
  }

  // A conjunction without the atoms another of it implies, dropped one at a time in order, each only for
  // an atom still there: what is left implies every atom dropped.
  Term without_implied_atoms(Term t) {
    for (std::size_t i = 0; i < t.size();) {
      bool implied = false;
      for (std::size_t j = 0; j < t.size() && !implied; ++j) implied = j != i && atom_implies(t[j], t[i]);
      if (implied) {
        t.erase(t.begin() + static_cast<std::ptrdiff_t>(i));
      } else {
        ++i;
      }
    }
    return t;
  }

  // The DNF in its form: shortest terms first; a term that implies one kept is dropped (it adds no word),
  // and kept ones that imply a new one give way to it. Every term dropped implies what is left.
  void normalise(Dnf& d) {
    for (Term& t : d) t = without_implied_atoms(std::move(t));
    std::ranges::sort(d, [](const Term& a, const Term& b) {
      return a.size() != b.size() ? a.size() < b.size() : a < b;
    });
    d.erase(std::unique(d.begin(), d.end()), d.end());
    Dnf kept;
    for (Term& t : d) {
      if (std::ranges::any_of(kept, [&](const Term& k) { return term_implies(t, k); })) continue;
      std::erase_if(kept, [&](const Term& k) { return term_implies(k, t); });
      kept.push_back(std::move(t));
    }
    d = std::move(kept);
  }

  int intern_atom(const Formula& f) {
    auto [it, inserted] = atom_ids_.try_emplace(f, static_cast<int>(atoms_.size()));
    if (inserted) {
      atoms_.push_back(f);
      atom_progress_.push_back(std::nullopt);
      atom_implies_.emplace_back();
    }
    return it->second;
  }

  int intern_dnf(Dnf d) {
    auto [it, inserted] = dnf_ids_.try_emplace(std::move(d), static_cast<int>(dnfs_.size()));
    if (inserted) dnfs_.push_back(&it->first);
    // Every state is one of these formulas, and a successor diagram makes them for all letters at once:
    // counted here, a task too large is refused before the first state's successors are all made.
    if (dnfs_.size() > kMaxFormulas) throw AutomatonTooLarge();
    return it->second;
  }

  int and_dnf(int a, int b) {
    if (a == kFalse || b == kFalse) return kFalse;
    if (a == kTrue || a == b) return b;
    if (b == kTrue) return a;
    auto [it, inserted] = and_memo_.try_emplace(pair_key(std::min(a, b), std::max(a, b)), 0);
    if (!inserted) return it->second;
    Dnf out;
    for (const Term& x : *dnfs_[a])
      for (const Term& y : *dnfs_[b]) {
        Term t;
        std::ranges::set_union(x, y, std::back_inserter(t));
        out.push_back(std::move(t));
      }
    normalise(out);
    return it->second = intern_dnf(std::move(out));
  }

  int or_dnf(int a, int b) {
    if (a == kTrue || b == kTrue) return kTrue;
    if (a == kFalse || a == b) return b;
    if (b == kFalse) return a;
    auto [it, inserted] = or_memo_.try_emplace(pair_key(std::min(a, b), std::max(a, b)), 0);
    if (!inserted) return it->second;
    Dnf out = *dnfs_[a];
    out.insert(out.end(), dnfs_[b]->begin(), dnfs_[b]->end());
    normalise(out);
    return it->second = intern_dnf(std::move(out));
  }

  // The DNF of a PNF formula over its atoms; <-> and ^ unfold into & and | of both polarities.
  int dnf_of(const Formula& f) {
    switch (f.op()) {
      case Op::True: return kTrue;
      case Op::False: return kFalse;
      case Op::And:
      case Op::Or: {
        int acc = f.op() == Op::And ? kTrue : kFalse;
        for (const Formula& c : f.children())
          acc = f.op() == Op::And ? and_dnf(acc, dnf_of(c)) : or_dnf(acc, dnf_of(c));
        return acc;
      }
      case Op::Equiv:
      case Op::Xor: {
        const bool exclusive = f.op() == Op::Xor;
        const Formula& a = f.child(0);
        const Formula& b = f.child(1);
        const Formula na = negated_normal_form(a);
        const Formula nb = negated_normal_form(b);
        return or_dnf(and_dnf(dnf_of(a), dnf_of(exclusive ? nb : b)),
                      and_dnf(dnf_of(na), dnf_of(exclusive ? b : nb)));
      }
      default: return intern_dnf(Dnf{Term{intern_atom(f)}});
    }
  }

  // ---- symbolic progression: for all letters at once, the formula that must hold from the next step ----

  static std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

  Node apply(bool conjunction, Node a, Node b) {
    auto& memo = conjunction ? and_nodes_ : or_nodes_;
    const int absorbing = conjunction ? kFalse : kTrue;
    if (dd_.is_leaf(a) && dd_.value(a) == absorbing) return a;
    if (dd_.is_leaf(b) && dd_.value(b) == absorbing) return b;
    if (dd_.is_leaf(a) && dd_.is_leaf(b))
      return dd_.leaf(conjunction ? and_dnf(dd_.value(a), dd_.value(b)) : or_dnf(dd_.value(a), dd_.value(b)));
    const std::uint64_t key = pair_key(std::min(a, b), std::max(a, b));
    if (auto it = memo.find(key); it != memo.end()) return it->second;
    const int v = std::min(dd_.var(a), dd_.var(b));
    const Node low = apply(conjunction, dd_.low_for(a, v), dd_.low_for(b, v));
    const Node high = apply(conjunction, dd_.high_for(a, v), dd_.high_for(b, v));
    const Node result = dd_.branch(v, low, high);
    memo.emplace(key, result);
    return result;
  }

  // The diagram of a PNF formula's Boolean structure over its atoms, `atom(id)` giving each atom's diagram:
  // progression and the stay evaluation differ only in that.
  template <typename AtomDiagram>
  Node combine(const Formula& f, AtomDiagram atom) {
    switch (f.op()) {
      case Op::True: return dd_.leaf(kTrue);
      case Op::False: return dd_.leaf(kFalse);
      case Op::And:
      case Op::Or: {
        const bool conjunction = f.op() == Op::And;
        Node acc = dd_.leaf(conjunction ? kTrue : kFalse);
        for (const Formula& c : f.children()) acc = apply(conjunction, acc, combine(c, atom));
        return acc;
      }
      case Op::Equiv:
      case Op::Xor: {
        const bool exclusive = f.op() == Op::Xor;
        const Node a = combine(f.child(0), atom);
        const Node b = combine(f.child(1), atom);
        const Node na = combine(negated_normal_form(f.child(0)), atom);
        const Node nb = combine(negated_normal_form(f.child(1)), atom);
        return apply(false, apply(true, a, exclusive ? nb : b), apply(true, na, exclusive ? b : nb));
      }
      default: return atom(intern_atom(f));
    }
  }

  // The same over a state's DNF.
  template <typename AtomDiagram>
  Node combine_state(int dnf, AtomDiagram atom) {
    Node acc = dd_.leaf(kFalse);
    for (const Term& t : *dnfs_[dnf]) {
      Node term = dd_.leaf(kTrue);
      for (int id : t) term = apply(true, term, atom(id));
      acc = apply(false, acc, term);
    }
    return acc;
  }

  Node progress_formula(const Formula& f) {
    return combine(f, [this](int id) { return progress_atom(id); });
  }

  Node progress_atom(int id) {
    if (atom_progress_[id]) return *atom_progress_[id];
    const Formula f = atoms_[id];
    const Node self = dd_.leaf(intern_dnf(Dnf{Term{id}}));  // "the atom itself, from the next step on"
    Node result;
    switch (f.op()) {
      case Op::Atom:
      case Op::Not: {
        const bool positive = f.op() == Op::Atom;
        const std::string& name = positive ? f.name() : f.child(0).name();
        const int var = static_cast<int>(std::ranges::find(props_, name) - props_.begin());
        result = dd_.branch(var, dd_.leaf(positive ? kFalse : kTrue), dd_.leaf(positive ? kTrue : kFalse));
        break;
      }
      case Op::Next: result = dd_.leaf(dnf_of(f.child(0))); break;
      case Op::Finally:  // F a = a | X F a
        result = apply(false, progress_formula(f.child(0)), self);
        break;
      case Op::Until:  // a U b = b | (a & X(a U b))
        result = apply(false, progress_formula(f.child(1)), apply(true, progress_formula(f.child(0)), self));
        break;
      case Op::StrongRelease:  // a M b = b & (a | X(a M b))
      case Op::Release:        // a R b = b & (a | X(a R b))
        result = apply(true, progress_formula(f.child(1)), apply(false, progress_formula(f.child(0)), self));
        break;
      case Op::Globally:  // G a = a & X G a
        result = apply(true, progress_formula(f.child(0)), self);
        break;
      case Op::WeakUntil:  // a W b = b | (a & X(a W b))
        result = apply(false, progress_formula(f.child(1)), apply(true, progress_formula(f.child(0)), self));
        break;
      default: throw std::logic_error("translate: operator not in positive normal form");
    }
    atom_progress_[id] = result;
    return result;
  }

  // ---- the truth of a formula on the word that repeats one letter forever, for all letters at once ----
  // On a constant word X f, F f and G f mean f; f U g and f R g mean g; f W g means f | g, f M g f & g.

  Node stay_formula(const Formula& f) {
    return combine(f, [this](int id) { return stay_atom(id); });
  }

  Node stay_atom(int id) {
    if (atom_stay_.size() <= static_cast<std::size_t>(id)) atom_stay_.resize(atoms_.size());
    if (atom_stay_[id]) return *atom_stay_[id];
    const Formula f = atoms_[id];
    Node result;
    switch (f.op()) {
      case Op::Atom:
      case Op::Not: result = progress_atom(id); break;  // a literal: true or false at once
      case Op::Next:
      case Op::Finally:
      case Op::Globally: result = stay_formula(f.child(0)); break;
      case Op::Until:
      case Op::Release: result = stay_formula(f.child(1)); break;
      case Op::WeakUntil: result = apply(false, stay_formula(f.child(0)), stay_formula(f.child(1))); break;
      case Op::StrongRelease: result = apply(true, stay_formula(f.child(0)), stay_formula(f.child(1))); break;
      default: throw std::logic_error("translate: operator not in positive normal form");
    }
    atom_stay_[id] = result;
    return result;
  }

  // The successor keys of a stop-and-stay state: leaf d of `successors` and leaf b of `stays` for the
  // same letter make the key 2d + b.
  Node pair_keys(Node successors, Node stays) {
    if (dd_.is_leaf(successors) && dd_.is_leaf(stays)) {
      return dd_.leaf(2 * dd_.value(successors) + (dd_.value(stays) == kTrue ? 1 : 0));
    }
    const std::uint64_t key = pair_key(successors, stays);
    if (auto it = pair_nodes_.find(key); it != pair_nodes_.end()) return it->second;
    const int v = std::min(dd_.var(successors), dd_.var(stays));
    const Node low = pair_keys(dd_.low_for(successors, v), dd_.low_for(stays, v));
    const Node high = pair_keys(dd_.high_for(successors, v), dd_.high_for(stays, v));
    const Node result = dd_.branch(v, low, high);
    pair_nodes_.emplace(key, result);
    return result;
  }

  // The successors of a state by letter, as a diagram whose leaves are state keys.
  Node successor_keys(int key) {
    if (!stop_and_stay_) return progress_state(key);
    const int dnf = key / 2;
    return pair_keys(progress_state(dnf), combine_state(dnf, [this](int id) { return stay_atom(id); }));
  }

  Node progress_state(int dnf) {
    return combine_state(dnf, [this](int id) { return progress_atom(id); });
  }

  // ---- the automaton ----

  void explore(int initial) {
    state_of_key_.emplace(initial, 0);
    state_keys_.push_back(initial);
    for (std::size_t s = 0; s < state_keys_.size(); ++s) {
      const Node root = successor_keys(state_keys_[s]);
      roots_.push_back(root);
      std::vector<int> successors;
      for (int key : dd_.leaf_values(root)) {
        auto [it, inserted] = state_of_key_.try_emplace(key, static_cast<int>(state_keys_.size()));
        if (inserted) state_keys_.push_back(key);
        if (state_keys_.size() > kMaxAutomatonStates) throw AutomatonTooLarge();
        successors.push_back(it->second);
      }
      successors_.push_back(std::move(successors));
    }
  }

  // A state is good (its formula holds on every infinite word) iff every infinite path from it reaches
  // the state `true`: for co-safe formulas a word is a model exactly when some finite prefix of it
  // progresses the formula to true. Least fixpoint: `true`, then states all of whose successors are good.
  std::vector<bool> good_states() const {
    const std::size_t n = state_keys_.size();
    std::vector<std::vector<int>> predecessors(n);
    std::vector<int> pending(n, 0);  // successors not yet known to be good
    for (std::size_t s = 0; s < n; ++s) {
      for (int t : successors_[s]) {
        predecessors[t].push_back(static_cast<int>(s));
        ++pending[s];
      }
    }
    std::vector<bool> good(n, false);
    std::deque<int> queue;
    if (auto it = state_of_key_.find(kTrue); it != state_of_key_.end()) {
      good[it->second] = true;
      queue.push_back(it->second);
    }
    while (!queue.empty()) {
      const int t = queue.front();
      queue.pop_front();
      for (int s : predecessors[t])
        if (!good[s] && --pending[s] == 0) {
          good[s] = true;
          queue.push_back(s);
        }
    }
    return good;
  }

  // Moore partition refinement on the symbolic transition functions: two states stay together while
  // they are in the same class and their diagrams, with leaves replaced by classes, are the same node.
  Dfa minimise(const std::vector<bool>& good) {
    const std::size_t n = state_keys_.size();
    std::vector<int> cls(n);
    std::size_t classes = 0;
    {
      int id_of[2] = {-1, -1};  // dense class ids, in order of first appearance
      for (std::size_t s = 0; s < n; ++s) {
        int& id = id_of[good[s] ? 1 : 0];
        if (id < 0) id = static_cast<int>(classes++);
        cls[s] = id;
      }
    }
    DecisionDiagram sig_dd;
    std::vector<Node> sig(n);
    while (true) {
      sig_dd = DecisionDiagram();
      std::unordered_map<Node, Node> memo;
      for (std::size_t s = 0; s < n; ++s) sig[s] = relabel(roots_[s], cls, sig_dd, memo);
      std::map<std::pair<int, Node>, int> ids;
      std::vector<int> next(n);
      for (std::size_t s = 0; s < n; ++s)
        next[s] = ids.try_emplace({cls[s], sig[s]}, static_cast<int>(ids.size())).first->second;
      // No class split: the partition is stable, and `sig` is written in the numbering of `cls`.
      if (ids.size() == classes) break;
      cls = std::move(next);
      classes = ids.size();
    }
    // `sig` now maps each state to its class's transitions over the stable classes.
    return build(cls, classes, good, sig_dd, sig);
  }

  Node relabel(Node n, const std::vector<int>& cls, DecisionDiagram& out, std::unordered_map<Node, Node>& memo) {
    if (auto it = memo.find(n); it != memo.end()) return it->second;
    const Node r = dd_.is_leaf(n) ? out.leaf(cls[state_of_key_.at(dd_.value(n))])
                                  : out.branch(dd_.var(n), relabel(dd_.low(n), cls, out, memo),
                                               relabel(dd_.high(n), cls, out, memo));
    memo.emplace(n, r);
    return r;
  }

  Dfa build(const std::vector<int>& cls, std::size_t classes, const std::vector<bool>& good,
            const DecisionDiagram& dd, const std::vector<Node>& sig) const {
    // One representative per class; number classes breadth-first from the start, targets in edge order.
    std::vector<int> representative(classes, -1);
    for (std::size_t s = 0; s < cls.size(); ++s)
      if (representative[cls[s]] < 0) representative[cls[s]] = static_cast<int>(s);
    std::vector<int> number(classes, -1);
    std::vector<int> order{cls[0]};
    number[cls[0]] = 0;
    Dfa dfa;
    dfa.propositions = props_;
    for (std::size_t i = 0; i < order.size(); ++i) {
      const Node root = sig[representative[order[i]]];
      std::vector<Edge> edges;
      for (auto& [c, condition] : conditions(dd, root)) {
        if (number[c] < 0) {
          number[c] = static_cast<int>(order.size());
          order.push_back(c);
        }
        edges.push_back(Edge{number[c], std::move(condition)});
      }
      std::ranges::sort(edges, {}, &Edge::target);
      dfa.edges.push_back(std::move(edges));
      dfa.accepting.push_back(good[representative[order[i]]]);
    }
    return dfa;
  }

  // For each leaf of `root` (in order of first appearance), the letters that lead to it, as a short
  // cover of cubes: the diagram's paths to the leaf, each widened by dropping the literals it does not
  // need.
  std::vector<std::pair<int, Condition>> conditions(const DecisionDiagram& dd, Node root) const {
    std::vector<std::pair<int, Cube>> paths;
    Cube path;
    collect_paths(dd, root, path, paths);
    std::vector<std::pair<int, Condition>> out;
    std::unordered_map<int, std::size_t> slot;  // target -> index in `out`
    std::unordered_map<int, int> path_count;
    for (const auto& p : paths) ++path_count[p.first];
    std::vector<signed char> assignment(props_.size(), -1);
    for (auto& path_to_target : paths) {
      const int target = path_to_target.first;
      Cube& cube = path_to_target.second;  // a reference, not a structured binding: the lambdas capture it
      // Dropping a literal would let the path continue into the other branch of its test, which then
      // has to reach this target by another path; with only one path to the target, nothing to widen.
      const bool widen = path_count[target] > 1;
      for (const Literal& l : cube) assignment[l.proposition] = l.positive;
      for (std::size_t i = 0; widen && i < cube.size();) {
        assignment[cube[i].proposition] = -1;
        if (only_leads_to(dd, root, assignment, target)) {
          cube.erase(cube.begin() + static_cast<std::ptrdiff_t>(i));
        } else {
          assignment[cube[i].proposition] = cube[i].positive;
          ++i;
        }
      }
      for (const Literal& l : cube) assignment[l.proposition] = -1;
      auto [it, inserted] = slot.try_emplace(target, out.size());
      if (inserted) out.emplace_back(target, Condition{});
      std::vector<Cube>& cubes = out[it->second].second.cubes;
      const bool subsumed = std::ranges::any_of(cubes, [&](const Cube& c) {
        return std::ranges::all_of(c, [&](const Literal& l) { return std::ranges::find(cube, l) != cube.end(); });
      });
      if (!subsumed) cubes.push_back(std::move(cube));
    }
    // In proposition order, for people reading the labels.
    for (auto& [target, condition] : out)
      std::ranges::sort(condition.cubes, [](const Cube& a, const Cube& b) {
        return std::ranges::lexicographical_compare(a, b, [](const Literal& x, const Literal& y) {
          return x.proposition != y.proposition ? x.proposition < y.proposition : x.positive > y.positive;
        });
      });
    return out;
  }

  void collect_paths(const DecisionDiagram& dd, Node n, Cube& path, std::vector<std::pair<int, Cube>>& out) const {
    if (dd.is_leaf(n)) {
      // The edges' labels grow with the states times the letters that tell their targets apart: counted
      // here, where a task of many independent obligations makes them.
      if (++paths_made_ > kMaxLabelCubes) throw AutomatonTooLarge();
      out.emplace_back(dd.value(n), path);
      return;
    }
    path.push_back(Literal{dd.var(n), false});
    collect_paths(dd, dd.low(n), path, out);
    path.back().positive = true;
    collect_paths(dd, dd.high(n), path, out);
    path.pop_back();
  }

  static bool only_leads_to(const DecisionDiagram& dd, Node n, const std::vector<signed char>& assignment, int target) {
    if (dd.is_leaf(n)) return dd.value(n) == target;
    const signed char a = assignment[dd.var(n)];
    if (a >= 0) return only_leads_to(dd, a ? dd.high(n) : dd.low(n), assignment, target);
    return only_leads_to(dd, dd.low(n), assignment, target) && only_leads_to(dd, dd.high(n), assignment, target);
  }

  std::vector<std::string> props_;
  bool stop_and_stay_;
  std::vector<Formula> atoms_;
  std::unordered_map<Formula, int> atom_ids_;
  detail::Implication implies_;
  static constexpr signed char kUnknown = -1;
  std::vector<std::vector<signed char>> atom_implies_;  // [x][y]: atom x implies atom y (1), not shown (0)
  std::vector<std::optional<Node>> atom_progress_;
  std::unordered_map<Dnf, int, VectorHash> dnf_ids_;
  std::vector<const Dnf*> dnfs_;  // by id; node-based map keys do not move
  std::unordered_map<std::uint64_t, int> and_memo_;
  std::unordered_map<std::uint64_t, int> or_memo_;
  DecisionDiagram dd_;
  std::unordered_map<std::uint64_t, Node> and_nodes_;
  std::unordered_map<std::uint64_t, Node> or_nodes_;
  std::unordered_map<std::uint64_t, Node> pair_nodes_;
  std::vector<std::optional<Node>> atom_stay_;
  std::unordered_map<int, int> state_of_key_;
  std::vector<int> state_keys_;
  std::vector<Node> roots_;                   // per state: its successor by letter, as a diagram
  mutable std::size_t paths_made_ = 0;        // by collect_paths, for every state
  std::vector<std::vector<int>> successors_;  // per state: its distinct successors
};

}  // namespace

AutomatonTooLarge::AutomatonTooLarge()
    : std::runtime_error("the task's automaton would be too large (over " + std::to_string(kMaxAutomatonStates) +
                         " states, or edges labelled by over " + std::to_string(kMaxLabelCubes) +
                         " cubes): each thing the task asks for in any order, or again and again, doubles it; ask "
                         "for fewer at once, in an order (F(a & F b) rather than F a & F b), or through groups "
                         "(docs/scenarios.md#groups)") {}

Dfa translate(const Formula& f) {
  const Formula pnf = positive_normal_form(f);
  const Acceptance acceptance =
      classify(pnf) == TaskClass::kCoSafe ? Acceptance::kGoodPrefix : Acceptance::kStopAndStay;
  return Translator(propositions(f), acceptance).run(pnf);
}

}  // namespace physltl::ltl
