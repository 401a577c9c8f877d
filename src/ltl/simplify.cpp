#include "physltl/ltl/simplify.h"

#include "normal_form.h"

#include <algorithm>
#include <array>

namespace physltl::ltl {

namespace {

bool contains(std::span<const std::string> names, const std::string& name) {
  return std::ranges::find(names, name) != names.end();
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Invalid propositions that occur in `f`, in the order the caller listed them.
std::vector<std::string> invalid_in(const Formula& f, std::span<const std::string> invalid) {
  const std::vector<std::string> props = propositions(f);
  std::vector<std::string> out;
  for (const std::string& p : invalid)
    if (contains(props, p) && !contains(out, p)) out.push_back(p);
  return out;
}

std::vector<std::string> dropped_from(const Formula& before, const std::optional<Formula>& after) {
  const std::vector<std::string> kept = after ? propositions(*after) : std::vector<std::string>{};
  std::vector<std::string> out;
  for (const std::string& p : propositions(before))
    if (!contains(kept, p)) out.push_back(p);
  return out;
}

// Rebuilds `f` with child `i` replaced.
Formula with_child(const Formula& f, std::size_t i, Formula child) {
  std::vector<Formula> children(f.children().begin(), f.children().end());
  children[i] = std::move(child);
  switch (f.children().size()) {
    case 1: return Formula::unary(f.op(), std::move(children[0]), f.origin());
    case 2:
      if (f.op() != Op::And && f.op() != Op::Or)
        return Formula::binary(f.op(), std::move(children[0]), std::move(children[1]), f.origin());
      [[fallthrough]];
    default: return Formula::nary(f.op(), std::move(children), f.origin());
  }
}

// The path of child indices from the root to the first occurrence of atom `name`, if any.
bool path_to(const Formula& f, const std::string& name, std::vector<std::size_t>& path) {
  if (f.op() == Op::Atom) return f.name() == name;
  for (std::size_t i = 0; i < f.children().size(); ++i) {
    path.push_back(i);
    if (path_to(f.child(i), name, path)) return true;
    path.pop_back();
  }
  return false;
}

struct ListStep {
  std::optional<Formula> formula;
  std::optional<Formula> deleted;  // the operand of | that went away
};

// Algorithm 1 for one occurrence: climb from the atom to the first list whose operators include |
// (an operand of an Or node) and delete it, or fail at the root.
ListStep simplify_occurrence(const Formula& root, const std::vector<std::size_t>& path) {
  std::vector<Formula> chain{root};  // chain[k] is the node at depth k of the path
  for (std::size_t i : path) chain.push_back(chain.back().child(i));
  for (std::size_t depth = path.size(); depth-- > 0;) {
    const Formula& parent = chain[depth];
    if (parent.op() != Op::Or) continue;
    std::vector<Formula> rest;
    for (std::size_t i = 0; i < parent.children().size(); ++i)
      if (i != path[depth]) rest.push_back(parent.child(i));
    Formula replaced = Formula::nary(Op::Or, std::move(rest), parent.origin());
    for (std::size_t k = depth; k-- > 0;) replaced = with_child(chain[k], path[k], std::move(replaced));
    return {replaced, chain[depth + 1]};
  }
  return {};
}

// `f` with false for the invalid propositions and true for those that always hold.
Formula substitute_constants(const Formula& f, std::span<const std::string> invalid,
                             std::span<const std::string> always_true) {
  if (f.op() == Op::Atom) {
    if (contains(invalid, f.name())) return Formula::ff();
    return contains(always_true, f.name()) ? Formula::tt() : f;
  }
  Formula out = f;
  for (std::size_t i = 0; i < f.children().size(); ++i) {
    Formula c = substitute_constants(f.child(i), invalid, always_true);
    if (!(c == f.child(i))) out = with_child(out, i, std::move(c));
  }
  return out;
}

// How an invalid proposition is used in a PNF formula: visits (positive) and avoidances (negated).
void count_uses(const Formula& f, const std::string& name, int& visits, int& avoids) {
  if (f.op() == Op::Atom) {
    visits += f.name() == name;
    return;
  }
  if (f.op() == Op::Not && f.child(0).op() == Op::Atom) {
    avoids += f.child(0).name() == name;
    return;
  }
  for (const Formula& c : f.children()) count_uses(c, name, visits, avoids);
}

std::string plural(int n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

Simplification simplify_by_lists(const Formula& f, std::span<const std::string> invalid) {
  const Formula pnf = positive_normal_form(f);
  const std::vector<std::string> bad = invalid_in(pnf, invalid);
  if (bad.empty()) return {pnf, {}, "no invalid proposition occurs in the formula; nothing to simplify"};

  Formula current = pnf;
  std::string explanation;
  for (const std::string& p : bad) {
    std::vector<std::size_t> path;
    while (path.clear(), path_to(current, p, path)) {
      ListStep step = simplify_occurrence(current, path);
      if (!step.formula) {
        explanation += (explanation.empty() ? "" : "; ") + p +
                       " is invalid and no | lies between it and the root of the formula, so the task "
                       "cannot be done without it: infeasible";
        return {std::nullopt, dropped_from(pnf, std::nullopt), explanation};
      }
      explanation += (explanation.empty() ? "" : "; ") + p + " is invalid: the alternative `" +
                     to_string(*step.deleted) + "` of an | is deleted";
      current = *step.formula;
    }
  }
  std::vector<std::string> dropped = dropped_from(pnf, current);
  explanation += "; result: " + to_string(current);
  return {current, std::move(dropped), explanation};
}

Simplification simplify_semantically(const Formula& f, std::span<const std::string> invalid,
                                     std::span<const std::string> always_true) {
  const Formula pnf = positive_normal_form(f);
  const std::vector<std::string> bad = invalid_in(pnf, invalid);
  const std::vector<std::string> constant = invalid_in(pnf, always_true);
  if (bad.empty() && constant.empty()) return {pnf, {}, "no invalid proposition occurs in the formula; nothing to simplify"};

  std::string explanation;
  // `verbs`: what becomes of its visits, and of one avoidance and of several.
  const auto explain = [&](const std::string& p, const char* what, std::array<const char*, 3> verbs) {
    int visits = 0;
    int avoids = 0;
    count_uses(pnf, p, visits, avoids);
    explanation += (explanation.empty() ? "" : "; ") + p + what;
    if (visits > 0) explanation += ": its " + plural(visits, "visit") + verbs[0];
    if (avoids > 0) explanation += std::string(visits > 0 ? " and" : ":") + " its " + plural(avoids, "avoidance") +
                                   verbs[avoids == 1 ? 1 : 2];
  };
  for (const std::string& p : bad) {
    explain(p, " is invalid, so false on every run", {" can never happen", " always holds", " always hold"});
  }
  for (const std::string& p : constant) {
    explain(p, " always holds, so true on every run", {" always happen", " can never hold", " can never hold"});
  }
  const Formula result = positive_normal_form(substitute_constants(pnf, bad, constant));
  std::vector<std::string> fixed = bad;
  fixed.insert(fixed.end(), constant.begin(), constant.end());
  if (result.op() == Op::False) {
    explanation += constant.empty() ? "; every way to satisfy the task needs " + join(bad) + ": infeasible"
                                    : "; no way to satisfy the task is left with " + join(fixed) + " as they are: infeasible";
    return {std::nullopt, dropped_from(pnf, std::nullopt), explanation};
  }
  std::vector<std::string> dropped = dropped_from(pnf, result);
  std::vector<std::string> collateral;
  for (const std::string& d : dropped)
    if (!contains(fixed, d)) collateral.push_back(d);
  if (!collateral.empty()) explanation += "; also gone, with the alternatives or constraints that involved an invalid proposition: " + join(collateral);
  explanation += "; result: " + to_string(result);
  return {result, std::move(dropped), explanation};
}

}  // namespace physltl::ltl
