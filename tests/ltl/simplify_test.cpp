#include "physltl/ltl/parser.h"
#include "physltl/ltl/simplify.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace physltl::ltl {
namespace {

using Names = std::vector<std::string>;

std::string result(const Simplification& s) { return s.formula ? to_string(*s.formula) : "infeasible"; }

TEST(SimplifyByLists, ReproducesThePapersExample) {
  const Simplification s = simplify_by_lists(parse("F p1 | (F p2 & F p3)"), Names{"p3"});
  EXPECT_EQ(result(s), "F p1");
  EXPECT_EQ(s.dropped, (Names{"p2", "p3"}));
  EXPECT_NE(s.explanation.find("`F p2 & F p3`"), std::string::npos) << s.explanation;
}

TEST(SimplifyByLists, ReproducesScenarioA) {
  EXPECT_EQ(result(simplify_by_lists(parse("F(p1 & F(p2 & F(p3 | p4)))"), Names{"p3"})), "F(p1 & F(p2 & F p4))");
}

TEST(SimplifyByLists, RejectsATaskWhoseOnlyWayNeedsAnInvalidProposition) {
  const Simplification s = simplify_by_lists(parse("F(p1 & F(p2 & F p3))"), Names{"p3"});
  EXPECT_FALSE(s.feasible());
  EXPECT_NE(s.explanation.find("infeasible"), std::string::npos);
}

TEST(SimplifyByLists, WronglyRejectsATaskThatOnlyAvoidsAnUnreachableRegion) {
  EXPECT_FALSE(simplify_by_lists(parse("(F p1 | F p2) & !p3 U p1"), Names{"p3"}).feasible());
}

TEST(SimplifyByLists, DropsEveryOccurrenceAndEveryInvalidProposition) {
  EXPECT_EQ(result(simplify_by_lists(parse("F p1 | F p3 | (p3 U p2) | F p4"), Names{"p3", "p4"})), "F p1");
}

TEST(SimplifyByLists, LeavesAFormulaWithoutInvalidPropositionsAlone) {
  const Simplification s = simplify_by_lists(parse("F p1"), Names{"p9"});
  EXPECT_EQ(result(s), "F p1");
  EXPECT_TRUE(s.dropped.empty());
}

TEST(SimplifySemantically, KeepsATaskThatOnlyAvoidsAnUnreachableRegion) {
  const Simplification s = simplify_semantically(parse("(F p1 | F p2) & !p3 U p1"), Names{"p3"});
  EXPECT_EQ(result(s), "(F p1 | F p2) & F p1");
  EXPECT_NE(s.explanation.find("avoidance always holds"), std::string::npos) << s.explanation;
}

TEST(SimplifySemantically, ExplainsWhyATaskIsInfeasible) {
  const Simplification s = simplify_semantically(parse("F(p1 & F p3)"), Names{"p3"});
  EXPECT_FALSE(s.feasible());
  EXPECT_NE(s.explanation.find("visit can never happen"), std::string::npos) << s.explanation;
  EXPECT_NE(s.explanation.find("needs p3"), std::string::npos) << s.explanation;
}

TEST(SimplifySemantically, AgreesWithThePaperOnThePapersFormulaClasses) {
  // Sequencing, coverage, disjunction, and visit-with-avoid, each with some visited proposition invalid.
  const std::vector<std::pair<const char*, Names>> cases{
      {"F(p1 & F(p2 & F p3))", {"p2"}},
      {"F p1 & F p2 & F p3", {"p3"}},
      {"F p1 | F p2 | F p3", {"p1"}},
      {"F p1 | F p2 | F p3", {"p1", "p2", "p3"}},
      {"(F p1 | F p2) & !p3", {"p1"}},
      {"(F p1 | F p2) & !p3", {"p1", "p2"}},
      {"F p1 | (F p2 & F p3)", {"p3"}},
      {"F p1 | (F p2 & F p3)", {"p1"}},
      {"F(p1 & F(p2 & F(p3 | p4)))", {"p3"}},
      {"F(p1 & F(p2 & F(p3 | p4)))", {"p3", "p4"}},
  };
  for (const auto& [text, invalid] : cases) {
    const Formula f = parse(text);
    const Simplification paper = simplify_by_lists(f, invalid);
    const Simplification semantic = simplify_semantically(f, invalid);
    EXPECT_EQ(result(paper), result(semantic)) << text;
    EXPECT_EQ(paper.dropped, semantic.dropped) << text;
  }
}

TEST(SimplifySemantically, SubstitutesInsideEveryOperator) {
  EXPECT_EQ(result(simplify_semantically(parse("p3 U p1"), Names{"p3"})), "p1");
  EXPECT_EQ(result(simplify_semantically(parse("!p3 U p1"), Names{"p3"})), "F p1");
  EXPECT_EQ(result(simplify_semantically(parse("F p1 | !p3"), Names{"p3"})), "true");
  EXPECT_EQ(result(simplify_semantically(parse("X(p3 <-> p1)"), Names{"p3"})), "X !p1");
}

}  // namespace
}  // namespace physltl::ltl
