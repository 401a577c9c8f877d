#include "physltl/ltl/analysis.h"

#include "physltl/ltl/co_safety.h"
#include "exclusivity.h"
#include "physltl/ltl/lasso.h"
#include "normal_form.h"
#include "physltl/ltl/parser.h"
#include "physltl/ltl/translate.h"

#include <ostream>

namespace physltl::ltl {
namespace {

bool accepts_some_possible_trace_from(const Dfa& dfa, int state, const Exclusivity& exclusivity) {
  const std::vector<bool> reachable = exclusivity.reachable(dfa, state);
  for (std::size_t q = 0; q < dfa.size(); ++q) {
    if (reachable[q] && dfa.accepting[q]) return true;
  }
  return false;
}

bool accepts_some_possible_trace(const Dfa& dfa, const Exclusivity& exclusivity) {
  return accepts_some_possible_trace_from(dfa, dfa.start, exclusivity);
}

// Whether some short lasso over letters that can occur, one that need not stop, satisfies the task: then
// it is the stop-and-stay reading that leaves no run. Lassos up to four positions; small alphabets only.
bool some_short_lasso_satisfies(const Formula& f, const std::vector<std::string>& propositions,
                                const Exclusivity& exclusivity) {
  // 8^4 words of each length is plenty; beyond that, say nothing.
  const auto indices = exclusivity.letters(8);
  if (!indices) return false;
  std::vector<std::vector<std::string>> letters;
  for (const auto& letter : *indices) {
    letters.emplace_back();
    for (int p : letter) letters.back().push_back(propositions[static_cast<std::size_t>(p)]);
  }
  const std::size_t k = letters.size();
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

std::string unsatisfiable_reason(const Formula& task, const Dfa& dfa, const Exclusivity& exclusivity) {
  const bool objects = exclusivity.has_object_atoms();
  const std::string disjoint = objects ? "no run satisfies it: the robot, and each body, is in at most one region at a "
                                         "time (the regions are disjoint)"
                                       : "no run satisfies it: the robot is in at most one region at a time (the "
                                         "regions are disjoint)";
  if (dfa.acceptance == Acceptance::kGoodPrefix) return disjoint;
  std::string why = disjoint + (objects ? ", and a plan is a finite run after which the robot and the bodies stop and "
                                          "stay where they are forever"
                                        : ", and a plan is a finite run after which the robot stops and stays in its "
                                          "last region forever");
  if (some_short_lasso_satisfies(task, dfa.propositions, exclusivity)) {
    why += "; it is that reading which makes the task infeasible: a run that never stops could satisfy it";
  }
  return why;
}

}  // namespace

std::string Analysis::infeasibility() const {
  if (semantic && !semantic->feasible()) return semantic->explanation;
  return unsatisfiable.value_or("");
}

Analysis analyse(std::string_view text, std::span<const std::string> invalid, std::span<const std::string> always_true) {
  return analyse(parse(text), invalid, always_true);
}

Analysis analyse(const Formula& input, std::span<const std::string> invalid, std::span<const std::string> always_true) {
  const Formula pnf = positive_normal_form(input);
  Analysis a{input, pnf, classify(pnf), {invalid.begin(), invalid.end()}, {always_true.begin(), always_true.end()},
             {}, {}, {}, {}};
  std::optional<Formula> task = a.normal_form;
  if (!invalid.empty()) a.by_lists = simplify_by_lists(a.normal_form, invalid);
  if (!invalid.empty() || !always_true.empty()) {
    a.semantic = simplify_semantically(a.normal_form, invalid, always_true);
    task = a.semantic->formula;
  }
  if (!task) return a;
  a.task_class = classify(*task);
  Dfa dfa = translate(*task);
  const Exclusivity exclusivity(dfa.propositions);
  if (!accepts_some_possible_trace(dfa, exclusivity)) {
    a.unsatisfiable = unsatisfiable_reason(*task, dfa, exclusivity);
  } else {
    a.dfa = std::move(dfa);
  }
  return a;
}

bool accepts_after(const Dfa& dfa, std::span<const int> first) {
  return accepts_some_possible_trace_from(dfa, dfa.step(dfa.start, first), Exclusivity(dfa.propositions));
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
  const auto names = [](const std::vector<std::string>& list) {
    std::string joined;
    for (const std::string& p : list) joined += (joined.empty() ? "" : ", ") + p;
    return joined;
  };
  if (!a.invalid.empty()) out << "invalid:     " << names(a.invalid) << "\n";
  if (!a.always_true.empty()) out << "always true: " << names(a.always_true) << "\n";
  if (a.by_lists) write_simplification(out, "paper:       ", *a.by_lists);
  if (a.semantic) write_simplification(out, "semantic:    ", *a.semantic);
  if (a.by_lists && a.by_lists->feasible() != a.semantic->feasible())
    out << "note:        the paper's list rule and the semantic one disagree; the planner uses the semantic one\n";
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
