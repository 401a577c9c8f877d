#include "physltl/ltl/analysis.h"

#include "physltl/ltl/co_safety.h"
#include "physltl/ltl/parser.h"
#include "physltl/ltl/translate.h"

#include <ostream>

namespace physltl::ltl {

Analysis analyse(std::string_view text, std::span<const std::string> invalid) {
  const Formula input = parse(text);
  Analysis a{input, require_co_safe(input), {invalid.begin(), invalid.end()}, {}, {}, {}};
  std::optional<Formula> task = a.normal_form;
  if (!invalid.empty()) {
    a.by_lists = simplify_by_lists(a.normal_form, invalid);
    a.semantic = simplify_semantically(a.normal_form, invalid);
    task = a.semantic->formula;
  }
  if (task) a.dfa = translate(*task);
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
  out << "class:       syntactically co-safe\n";
  if (a.by_lists) {
    std::string names;
    for (const std::string& p : a.invalid) names += (names.empty() ? "" : ", ") + p;
    out << "invalid:     " << names << "\n";
    write_simplification(out, "paper:       ", *a.by_lists);
    write_simplification(out, "semantic:    ", *a.semantic);
    if (a.by_lists->feasible() != a.semantic->feasible())
      out << "note:        the paper's list rule and the semantic one disagree; the planner uses the semantic one\n";
  }
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
