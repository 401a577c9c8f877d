#include "physltl/ltl/co_safety.h"
#include "physltl/ltl/parser.h"
#include "physltl/ltl/translate.h"

#include <gtest/gtest.h>

#include <string>

namespace physltl::ltl {
namespace {

std::string sequencing(int n) {
  std::string f = "F p" + std::to_string(n);
  for (int i = n - 1; i >= 1; --i) f = "F(p" + std::to_string(i) + " & " + f + ")";
  return f;
}

std::string joined(int n, const char* op) {
  std::string f;
  for (int i = 1; i <= n; ++i) f += (i > 1 ? op : "") + std::string("F p") + std::to_string(i);
  return f;
}

Dfa dfa_of(const std::string& text) { return translate(parse(text)); }

TEST(Translate, SequencingOfNRegionsHasNPlusOneStates) {
  for (int n = 1; n <= 10; ++n) EXPECT_EQ(dfa_of(sequencing(n)).size(), static_cast<std::size_t>(n + 1)) << n;
}

TEST(Translate, CoverageOfNRegionsHasTwoToTheNStates) {
  for (int n = 1; n <= 10; ++n) EXPECT_EQ(dfa_of(joined(n, " & ")).size(), std::size_t{1} << n) << n;
}

// Past its bounds the automaton is refused, not built: covering 20 or 64 regions in any order would be
// 2^20 or 2^64 states (the first took 22 GB before the kernel ended the run), and 11 obligations
// G(a -> F b) labels past 60 s and 5.5 GB. Coverage of 11 regions (2,048 states) and 7 obligations are made.
TEST(Translate, ATaskOfTooManyStatesIsRefusedAndOneBelowTheBoundIsNot) {
  EXPECT_EQ(dfa_of(joined(11, " & ")).size(), std::size_t{1} << 11);
  for (int n : {12, 20, 64}) EXPECT_THROW(dfa_of(joined(n, " & ")), AutomatonTooLarge) << n;
  const auto obligations = [](int n) {
    std::string f;
    for (int i = 1; i <= n; ++i) f += (i > 1 ? " & " : "") + std::string("G(a") + std::to_string(i) + " -> F b" + std::to_string(i) + ")";
    return f;
  };
  EXPECT_EQ(dfa_of(obligations(7)).size(), 129u);
  EXPECT_THROW(dfa_of(obligations(11)), AutomatonTooLarge);
  EXPECT_EQ(dfa_of(sequencing(200)).size(), 201u);  // long but in an order: linear
}

// Each stage of a chain of untils implies the stages before it ((a2|b2) U ... implies (a1|b1) U (a2|b2) U
// ...): a letter that meets several stages at once leads to the furthest, and the automaton is a line.
// Until the translation knew that, each set of stages met at once was a state of its own until minimising:
// 2^14 of them for 15 stages, refused as too large.
TEST(Translate, AChainOfUntilsHasAStatePerStage) {
  for (int n : {3, 15, 40}) {
    std::string f;
    for (int i = 1; i <= n; ++i) f += (i > 1 ? " U " : "") + std::string("(a") + std::to_string(i) + " | b" + std::to_string(i) + ")";
    EXPECT_EQ(dfa_of(f).size(), static_cast<std::size_t>(n + 1)) << f;
  }
}

TEST(Translate, DisjunctionOfNRegionsHasTwoStates) {
  for (int n = 1; n <= 10; ++n) {
    const Dfa dfa = dfa_of(joined(n, " | "));
    EXPECT_EQ(dfa.size(), 2u) << n;
    // Two edges: the self-loop while no region is visited, and "any region" to the accepting sink.
    EXPECT_EQ(dfa.edges[0].size(), 2u);
    EXPECT_EQ(dfa.edges[0][1].condition.cubes.size(), static_cast<std::size_t>(n));
  }
}

TEST(Translate, AcceptsTheEmptyPrefixOfAFormulaTrueOnEveryWord) {
  const Dfa dfa = dfa_of("F a | X F !a");
  EXPECT_EQ(dfa.size(), 1u);
  EXPECT_TRUE(dfa.accepting[0]);
}

TEST(Translate, AcceptsOnlyOnceTheGoodPrefixIsComplete) {
  const Dfa dfa = dfa_of("F(p1 & F p2)");
  const int p1 = dfa.proposition_index("p1");
  const int p2 = dfa.proposition_index("p2");
  using Trace = std::vector<std::vector<int>>;
  EXPECT_FALSE(dfa.accepts(Trace{}));
  EXPECT_FALSE(dfa.accepts(Trace{{p2}, {p1}}));
  EXPECT_TRUE(dfa.accepts(Trace{{p2}, {p1}, {}, {p2}}));
  EXPECT_TRUE(dfa.accepts(Trace{{p1}, {p2}, {}}));  // the accepting sink stays accepting
}

TEST(Translate, HasARejectingSinkWhenTheTaskCanFail) {
  const Dfa dfa = dfa_of("!p3 U p1");
  EXPECT_EQ(dfa.size(), 3u);
  const int p3 = dfa.proposition_index("p3");
  const int dead = dfa.step(dfa.start, std::vector<int>{p3});
  EXPECT_FALSE(dfa.accepting[dead]);
  EXPECT_EQ(dfa.step(dead, std::vector<int>{dfa.proposition_index("p1")}), dead);
}

TEST(Translate, IsCompleteAndDeterministicOnEveryLetter) {
  const Dfa dfa = dfa_of("(a U b) & X(c M a) | F(b & X !c)");
  const std::size_t n = dfa.propositions.size();
  for (std::size_t s = 0; s < dfa.size(); ++s) {
    for (unsigned letter = 0; letter < (1u << n); ++letter) {
      bool truth[8];
      for (std::size_t i = 0; i < n; ++i) truth[i] = (letter >> i) & 1;
      int matching = 0;
      for (const Edge& e : dfa.edges[s]) matching += e.condition.holds(std::span<const bool>(truth, n));
      EXPECT_EQ(matching, 1) << "state " << s << " letter " << letter;
    }
  }
}

TEST(Translate, MatchesTheMinimalSizesOfSmallKnownAutomata) {
  EXPECT_EQ(dfa_of("true").size(), 1u);
  EXPECT_EQ(dfa_of("false").size(), 1u);
  EXPECT_FALSE(dfa_of("false").accepting[0]);
  EXPECT_EQ(dfa_of("a").size(), 3u);          // start, accept, reject
  EXPECT_EQ(dfa_of("X a").size(), 4u);        // start, wait-for-a, accept, reject
  EXPECT_EQ(dfa_of("a U b").size(), 3u);
  EXPECT_EQ(dfa_of("a M b").size(), 3u);      // b U (a & b)
  EXPECT_EQ(dfa_of("F a & F a").size(), 2u);
  EXPECT_EQ(dfa_of("F(a | !a)").size(), 1u);  // valid once the first letter is read... and before
  EXPECT_EQ(dfa_of("X(a ^ b)").size(), 4u);
}

TEST(Translate, UsesTheFormulasPropositionsAsAlphabetInOrder) {
  EXPECT_EQ(dfa_of("F(kitchen & F(hall | kitchen))").propositions, (std::vector<std::string>{"kitchen", "hall"}));
}

bool accepts(const Dfa& dfa, std::vector<std::vector<int>> trace) { return dfa.accepts(trace); }

TEST(Translate, NeverGivesAStopAndStayAutomatonThatPrunesTheHazard) {
  const Dfa dfa = dfa_of("G !hazard");
  EXPECT_EQ(dfa.acceptance, Acceptance::kStopAndStay);
  EXPECT_EQ(dfa.size(), 3u);  // start, safe so far, entered the hazard (dead)
  EXPECT_TRUE(accepts(dfa, {{}, {}, {}}));
  EXPECT_FALSE(accepts(dfa, {{}, {0}, {}}));
}

TEST(Translate, CoSafeTasksKeepTheGoodPrefixAutomaton) {
  EXPECT_EQ(dfa_of("F(a & F b)").acceptance, Acceptance::kGoodPrefix);
}

TEST(Translate, EventuallyAlwaysAcceptsARunThatEndsInTheRegion) {
  const Dfa dfa = dfa_of("F G home");
  EXPECT_TRUE(accepts(dfa, {{}, {0}}));
  EXPECT_FALSE(accepts(dfa, {{0}, {}}));
  EXPECT_TRUE(accepts(dfa, {{0}, {}, {0}}));
}

TEST(Translate, AResponseLeavesNoRequestUnanswered) {
  const Dfa dfa = dfa_of("G(a -> F b)");  // propositions a, b
  EXPECT_TRUE(accepts(dfa, {{}, {}}));
  EXPECT_FALSE(accepts(dfa, {{0}, {}}));
  EXPECT_TRUE(accepts(dfa, {{0}, {}, {1}}));
  EXPECT_FALSE(accepts(dfa, {{0}, {1}, {0}}));
}

}  // namespace
}  // namespace physltl::ltl
