#include "physltl/ltl/analysis.h"
#include "physltl/ltl/co_safety.h"
#include "physltl/ltl/parser.h"

#include <gtest/gtest.h>

#include <sstream>

namespace physltl::ltl {
namespace {

using Names = std::vector<std::string>;

std::string summary(const char* text, const Names& invalid = {}) {
  std::ostringstream out;
  write_summary(out, analyse(text, invalid));
  return out.str();
}

TEST(Analysis, SummarisesAFormulaWithoutInvalidPropositions) {
  EXPECT_EQ(summary("p1 -> F p2"),
            "input:       p1 -> F p2\n"
            "normal form: !p1 | F p2\n"
            "class:       syntactically co-safe\n"
            "automaton:   3 states, 5 edges, 1 accepting, over 2 propositions\n");
}

TEST(Analysis, ShowsBothSimplificationsAndTheirDisagreement) {
  const std::string text = summary("(F p1 | F p2) & !p3 U p1", {"p3"});
  EXPECT_NE(text.find("paper:       infeasible\n"), std::string::npos) << text;
  EXPECT_NE(text.find("semantic:    (F p1 | F p2) & F p1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("disagree"), std::string::npos) << text;
  EXPECT_NE(text.find("automaton:   2 states"), std::string::npos) << text;
}

TEST(Analysis, TranslatesTheSemanticallySimplifiedTask) {
  const Analysis a = analyse("F(p1 & F(p2 & F(p3 | p4)))", Names{"p3"});
  ASSERT_TRUE(a.dfa);
  EXPECT_EQ(a.dfa->propositions, (Names{"p1", "p2", "p4"}));
  EXPECT_EQ(a.dfa->size(), 4u);
}

TEST(Analysis, ReportsAnInfeasibleTaskWithoutAnAutomaton) {
  const Analysis a = analyse("F(p1 & F p3)", Names{"p3"});
  EXPECT_FALSE(a.feasible());
  EXPECT_FALSE(a.dfa);
  std::ostringstream out;
  write_summary(out, a);
  EXPECT_NE(out.str().find("automaton:   none, the task is infeasible"), std::string::npos);
}

TEST(Analysis, PassesSyntaxAndClassErrorsOnToTheCaller) {
  EXPECT_THROW(analyse("F(p1 &", {}), ParseError);
  EXPECT_THROW(analyse("G p1", {}), NotCoSafeError);
}

}  // namespace
}  // namespace physltl::ltl
