#include "physltl/ltl/co_safety.h"
#include "normal_form.h"
#include "physltl/ltl/parser.h"

#include <gtest/gtest.h>

#include <string>

namespace physltl::ltl {
namespace {

std::string pnf(const char* text) { return to_string(positive_normal_form(parse(text))); }

TEST(NormalForm, PushesNegationsToTheAtoms) {
  EXPECT_EQ(pnf("!(a & F b)"), "!a | G !b");
  EXPECT_EQ(pnf("!(a U b)"), "!a R !b");
  EXPECT_EQ(pnf("!(a R b)"), "!a U !b");
  EXPECT_EQ(pnf("!(a W b)"), "!a M !b");
  EXPECT_EQ(pnf("!(a M b)"), "!a W !b");
  EXPECT_EQ(pnf("!X !a"), "X a");
  EXPECT_EQ(pnf("a -> F b"), "!a | F b");
  EXPECT_EQ(pnf("!(a -> b)"), "a & !b");
  EXPECT_EQ(pnf("!(a <-> b)"), "a ^ b");
  EXPECT_EQ(pnf("!(a ^ b)"), "a <-> b");
}

TEST(NormalForm, FoldsConstantsSoHarmlessGRWDisappear) {
  EXPECT_EQ(pnf("G true & F a"), "F a");
  EXPECT_EQ(pnf("a R true"), "true");
  EXPECT_EQ(pnf("true R F a"), "F a");
  EXPECT_EQ(pnf("true W a"), "true");
  EXPECT_EQ(pnf("false W F a"), "F a");
  EXPECT_EQ(pnf("false U a"), "a");
  EXPECT_EQ(pnf("true U a"), "F a");
  EXPECT_EQ(pnf("a M true"), "F a");
  EXPECT_EQ(pnf("X false | F false"), "false");
  EXPECT_EQ(pnf("(a <-> true) & (b ^ true)"), "a & !b");
  EXPECT_EQ(pnf("a & a & (a | false)"), "a");
}

TEST(NormalForm, KeepsTheOriginOfRewrittenOperators) {
  const Formula f = positive_normal_form(parse("a & !F b"));
  const Formula g = f.child(1);
  EXPECT_EQ(g.op(), Op::Globally);
  EXPECT_EQ(g.origin().column, 6u);
  EXPECT_EQ(g.origin().written, Op::Finally);
}

TEST(CoSafety, AcceptsThePapersFormulaClasses) {
  for (const char* text : {"F p1 & F p2 & F p3", "F(p1 & F(p2 & F p3))", "F p1 | F p2 | F p3",
                           "(F p1 | F p2) & !p3", "!p3 U p1", "a M b", "X X a", "(X a <-> b) & F c",
                           "G true & F a", "!G !a"}) {
    EXPECT_FALSE(find_co_safety_violation(positive_normal_form(parse(text)))) << text;
  }
}

TEST(CoSafety, RefusesGlobally) {
  const auto v = find_co_safety_violation(positive_normal_form(parse("F a & G b")));
  ASSERT_TRUE(v);
  EXPECT_EQ(v->op, Op::Globally);
  EXPECT_EQ(v->origin.column, 7u);
  EXPECT_NE(v->message().find("G at column 7"), std::string::npos) << v->message();
  EXPECT_NE(v->message().find("every position"), std::string::npos) << v->message();
}

TEST(CoSafety, ExplainsThatANegatedEventuallyIsAnAlways) {
  const auto v = find_co_safety_violation(positive_normal_form(parse("p1 -> F p2 & !F p3")));
  ASSERT_TRUE(v);
  EXPECT_EQ(v->origin.column, 15u);
  EXPECT_NE(v->message().find("F at column 15 is negated"), std::string::npos) << v->message();
  EXPECT_NE(v->message().find("so it is G"), std::string::npos) << v->message();
}

TEST(CoSafety, RefusesReleaseAndWeakUntilThatDoNotFoldAway) {
  EXPECT_EQ(find_co_safety_violation(positive_normal_form(parse("a R b")))->op, Op::Release);
  EXPECT_EQ(find_co_safety_violation(positive_normal_form(parse("a W b")))->op, Op::WeakUntil);
  EXPECT_EQ(find_co_safety_violation(positive_normal_form(parse("!(a U b)")))->op, Op::Release);
}

TEST(CoSafety, RefusesTemporalOperandsOfEquivalenceWhoseNegationLeavesTheClass) {
  const auto v = find_co_safety_violation(positive_normal_form(parse("F a <-> b")));
  ASSERT_TRUE(v);
  EXPECT_EQ(v->op, Op::Finally);
  EXPECT_EQ(v->context, Op::Equiv);
  EXPECT_NE(v->message().find("operand of <->"), std::string::npos) << v->message();
}

}  // namespace
}  // namespace physltl::ltl
