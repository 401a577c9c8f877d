#include "physltl/ltl/analysis.h"

#include "physltl/ltl/co_safety.h"
#include "physltl/ltl/lasso.h"
#include "physltl/ltl/normal_form.h"
#include "physltl/ltl/parser.h"
#include "physltl/ltl/translate.h"

#include <deque>
#include <ostream>

namespace physltl::ltl {
namespace {

// The letters a robot among disjoint regions can read: no proposition true, or exactly one.
std::vector<std::vector<int>> exclusive_letters(std::size_t propositions) {
  std::vector<std::vector<int>> letters{{}};
  for (std::size_t p = 0; p < propositions; ++p) letters.push_back({static_cast<int>(p)});
  return letters;
}

bool accepts_some_exclusive_trace(const Dfa& dfa) {
  const auto letters = exclusive_letters(dfa.propositions.size());
  std::vector<bool> seen(dfa.size(), false);
  std::deque<int> queue{dfa.start};
  seen[dfa.start] = true;
  while (!queue.empty()) {
    const int s = queue.front();
    queue.pop_front();
    for (const auto& letter : letters) {
      const int t = dfa.step(s, letter);
      if (dfa.accepting[t]) return true;
      if (!seen[t]) seen[t] = true, queue.push_back(t);
    }
  }
  return false;
}

// Whether some short lasso over exclusive letters, one that need not stop, satisfies the task: then it
// is the stop-and-stay reading that leaves no run. Lassos up to four positions; small alphabets only.
bool some_short_lasso_satisfies(const Formula& f, const std::vector<std::string>& propositions) {
  std::vector<std::vector<std::string>> letters{{}};
  for (const auto& p : propositions) letters.push_back({p});
  const std::size_t k = letters.size();
  if (k > 8) return false;  // 8^4 words of each length is plenty; beyond that, say nothing
  std::vector<std::vector<std::string>> word;
  for (std::size_t length = 1; length <= 4; ++length) {
    std::size_t words = 1;
    for (std::size_t i = 0; i < length; ++i) words *= k;
    word.resize(length);
    for (std::size_t code = 0; code < words; ++code) {
      std::size_t c = code;
      for (auto& letter : word) letter = letters[c % k], c /= k;
      for (std::size_t loop = 0; loop < length; ++loop) {
        if (holds_on_lasso(f, word, loop)) return true;
      }
    }
  }
  return false;
}

std::string unsatisfiable_reason(const Formula& task, const Dfa& dfa) {
  const std::string disjoint = "no run satisfies it: the robot is in at most one region at a time (the regions are disjoint)";
  if (dfa.acceptance == Acceptance::kGoodPrefix) return disjoint;
  std::string why = disjoint + ", and a plan is a finite run after which the robot stops and stays in its last region forever";
  if (some_short_lasso_satisfies(task, dfa.propositions)) {
    why += "; it is that reading which makes the task infeasible: a run that never stops could satisfy it";
  }
  return why;
}

}  // namespace

std::string Analysis::infeasibility() const {
  if (semantic && !semantic->feasible()) return semantic->explanation;
  return unsatisfiable.value_or("");
}

Analysis analyse(std::string_view text, std::span<const std::string> invalid) {
  const Formula input = parse(text);
  const Formula pnf = positive_normal_form(input);
  Analysis a{input, pnf, classify(pnf), {invalid.begin(), invalid.end()}, {}, {}, {}, {}};
  std::optional<Formula> task = a.normal_form;
  if (!invalid.empty()) {
    a.by_lists = simplify_by_lists(a.normal_form, invalid);
    a.semantic = simplify_semantically(a.normal_form, invalid);
    task = a.semantic->formula;
  }
  if (!task) return a;
  a.task_class = classify(*task);
  Dfa dfa = translate(*task);
  if (!accepts_some_exclusive_trace(dfa)) {
    a.unsatisfiable = unsatisfiable_reason(*task, dfa);
  } else {
    a.dfa = std::move(dfa);
  }
  return a;
}

namespace {

void write_simplification(std::ostream& out, const char* label, const Simplification& s) {
  out << label << (s.formula ? to_string(*s.formula) : "infeasible") << "\n";
  out << "  why:       " << s.explanation << "\n";
}

}  // namespace

void write_summary(std::ostream& out, const Analysis& a) {
  out << "input:       " << to_string(a.input) << "\n";
  out << "normal form: " << to_string(a.normal_form) << "\n";
  out << "class:       " << class_name(a.task_class) << "\n";
  if (auto why = find_co_safety_violation(a.normal_form)) out << "not co-safe: " << why->message() << "\n";
  out << "semantics:   " << semantics_of(a.task_class) << "\n";
  if (a.by_lists) {
    std::string names;
    for (const std::string& p : a.invalid) names += (names.empty() ? "" : ", ") + p;
    out << "invalid:     " << names << "\n";
    write_simplification(out, "paper:       ", *a.by_lists);
    write_simplification(out, "semantic:    ", *a.semantic);
    if (a.by_lists->feasible() != a.semantic->feasible())
      out << "note:        the paper's list rule and the semantic one disagree; the planner uses the semantic one\n";
  }
  if (a.unsatisfiable) out << "infeasible:  " << *a.unsatisfiable << "\n";
  if (!a.dfa) {
    out << "automaton:   none, the task is infeasible\n";
    return;
  }
  std::size_t accepting = 0;
  for (bool acc : a.dfa->accepting) accepting += acc;
  out << "automaton:   " << a.dfa->size() << (a.dfa->size() == 1 ? " state, " : " states, ")
      << a.dfa->edge_count() << (a.dfa->edge_count() == 1 ? " edge, " : " edges, ") << accepting
      << " accepting, over " << a.dfa->propositions.size()
      << (a.dfa->propositions.size() == 1 ? " proposition\n" : " propositions\n");
}

}  // namespace physltl::ltl
