#include "physltl/ltl/hoa.h"

#include <ostream>

namespace physltl::ltl {

namespace {

// HOA strings are double-quoted with backslash escapes.
void write_quoted(std::ostream& out, const std::string& s) {
  out << '"';
  for (char c : s) {
    if (c == '"' || c == '\\') out << '\\';
    out << c;
  }
  out << '"';
}

// A label in HOA's Boolean syntax over AP indices: "t", "0&!1", "0 | 1&2".
void write_label(std::ostream& out, const Condition& condition) {
  if (condition.cubes.empty()) {
    out << 'f';
    return;
  }
  for (std::size_t i = 0; i < condition.cubes.size(); ++i) {
    if (i > 0) out << " | ";
    const Cube& cube = condition.cubes[i];
    if (cube.empty()) out << 't';
    for (std::size_t j = 0; j < cube.size(); ++j) {
      if (j > 0) out << '&';
      if (!cube[j].positive) out << '!';
      out << cube[j].proposition;
    }
  }
}

}  // namespace

void write_hoa(std::ostream& out, const Dfa& dfa) {
  out << "HOA: v1\n";
  out << "States: " << dfa.size() << "\n";
  out << "Start: " << dfa.start << "\n";
  out << "AP: " << dfa.propositions.size();
  for (const std::string& p : dfa.propositions) {
    out << ' ';
    write_quoted(out, p);
  }
  out << "\n";
  out << "acc-name: Buchi\n";
  out << "Acceptance: 1 Inf(0)\n";
  out << "properties: trans-labels explicit-labels state-acc deterministic complete\n";
  out << "--BODY--\n";
  for (std::size_t s = 0; s < dfa.size(); ++s) {
    out << "State: " << s << (dfa.accepting[s] ? " {0}" : "") << "\n";
    for (const Edge& e : dfa.edges[s]) {
      out << '[';
      write_label(out, e.condition);
      out << "] " << e.target << "\n";
    }
  }
  out << "--END--\n";
}

}  // namespace physltl::ltl
