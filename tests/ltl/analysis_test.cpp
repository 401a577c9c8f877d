#include "physltl/ltl/analysis.h"
#include "physltl/ltl/co_safety.h"
#include "normal_form.h"
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
            "class:       co-safe\n"
            "semantics:   a plan satisfies it once every continuation would (the first good prefix)\n"
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

TEST(Analysis, PassesSyntaxErrorsOnToTheCaller) { EXPECT_THROW(analyse("F(p1 &", {}), ParseError); }

TEST(Analysis, NamesTheClassOfEveryKindOfTask) {
  EXPECT_EQ(analyse("F(p1 & F p2)", {}).task_class, TaskClass::kCoSafe);
  EXPECT_EQ(analyse("G !hazard", {}).task_class, TaskClass::kSafety);
  EXPECT_EQ(analyse("F goal & G !hazard", {}).task_class, TaskClass::kCoSafeAndSafety);
  EXPECT_EQ(analyse("G(a -> F b)", {}).task_class, TaskClass::kGeneral);
  EXPECT_EQ(analyse("F G home", {}).task_class, TaskClass::kGeneral);
  std::ostringstream out;
  write_summary(out, analyse("F goal & G !hazard", {}));
  EXPECT_NE(out.str().find("class:       co-safe and safety"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("stopping and staying"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("not co-safe: G at column 10"), std::string::npos) << out.str();
}

TEST(Formula, TheRegionsATaskAvoidsAreThoseItMentionsOnlyNegated) {
  const auto avoided = [](const char* text) { return avoided_propositions(positive_normal_form(parse(text))); };
  EXPECT_EQ(avoided("F goal & G !hazard"), std::vector<std::string>{"hazard"});
  EXPECT_EQ(avoided("!hazard U goal"), std::vector<std::string>{"hazard"});
  EXPECT_EQ(avoided("(F p1 | F p2) & G !p3"), std::vector<std::string>{"p3"});
  EXPECT_EQ(avoided("!F p3 & F p1"), std::vector<std::string>{"p3"});  // a negated visit is an avoidance
  EXPECT_TRUE(avoided("F a & !a").empty());  // visited too
  EXPECT_TRUE(avoided("F(a <-> !b)").empty());  // both polarities
}

// Regions are disjoint: the robot is never in two at once, so some tasks have no run at all.
TEST(Analysis, ATaskNoRunAmongDisjointRegionsSatisfiesIsInfeasibleWithoutSearching) {
  const Analysis both = analyse("F G a & F G b", {});
  EXPECT_FALSE(both.feasible());
  EXPECT_FALSE(both.dfa);
  EXPECT_NE(both.infeasibility().find("at most one region at a time"), std::string::npos) << both.infeasibility();
  EXPECT_FALSE(analyse("F(a & b)", {}).feasible());
  EXPECT_TRUE(analyse("F a & F b", {}).feasible());
}

// A letter is the robot's region plus one region or none for each body: bodies may share a region with
// each other and with the robot, but no body is in two regions at once.
TEST(Analysis, EachBodyIsInAtMostOneRegionButBodiesAndTheRobotMayShareOne) {
  EXPECT_TRUE(analyse("F(B1@dock & B2@dock)", {}).feasible());
  EXPECT_TRUE(analyse("F(crate@dock & dock)", {}).feasible());
  EXPECT_TRUE(analyse("F(B1@p2 & p1) & G !B3@aisle", {}).feasible());
  const Analysis twice = analyse("F(B1@dock & B1@bay)", {});
  EXPECT_FALSE(twice.feasible());
  EXPECT_NE(twice.infeasibility().find("each body, is in at most one region"), std::string::npos) << twice.infeasibility();
  EXPECT_FALSE(analyse("F(dock & bay) & F crate@dock", {}).feasible());
  EXPECT_FALSE(analyse("F G B1@dock & F G B1@bay", {}).feasible());
}

TEST(Analysis, APatrolIsInfeasibleBecauseTheRobotStopsAndStays) {
  const Analysis patrol = analyse("G F a & G F b", {});
  EXPECT_FALSE(patrol.feasible());
  const std::string why = patrol.infeasibility();
  EXPECT_NE(why.find("stops and stays"), std::string::npos) << why;
  EXPECT_NE(why.find("a run that never stops could satisfy it"), std::string::npos) << why;
  EXPECT_TRUE(analyse("G F a", {}).feasible());  // ends in a
}

// The polarity rule: an unreachable region is never entered, so avoiding it always holds.
TEST(Analysis, AnUnreachableRegionInANeverPartMakesThatPartTrue) {
  const std::vector<std::string> invalid{"p3"};
  const Analysis a = analyse("(F p1 | F p2) & G !p3", invalid);
  ASSERT_TRUE(a.feasible());
  EXPECT_EQ(to_string(*a.semantic->formula), "F p1 | F p2");
  EXPECT_EQ(a.task_class, TaskClass::kCoSafe);
}

}  // namespace
}  // namespace physltl::ltl
