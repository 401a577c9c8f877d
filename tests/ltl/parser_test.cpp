#include "physltl/ltl/parser.h"

#include <gtest/gtest.h>

#include <string>

namespace physltl::ltl {
namespace {

Formula atom(const char* name) { return Formula::atom(name); }
Formula un(Op op, Formula f) { return Formula::unary(op, std::move(f)); }
Formula bin(Op op, Formula a, Formula b) { return Formula::binary(op, std::move(a), std::move(b)); }

std::string reprint(const char* text) { return to_string(parse(text)); }

TEST(Parser, ReadsTheExamplesOfThePaperAndPrintsThemBack) {
  EXPECT_EQ(reprint("F(p1 & F(p2 & F(p3 | p4)))"), "F(p1 & F(p2 & F(p3 | p4)))");
  EXPECT_EQ(reprint("F p1 | (F p2 & F p3)"), "F p1 | (F p2 & F p3)");
  EXPECT_EQ(reprint("(F p1 | F p2) & !p3"), "(F p1 | F p2) & !p3");
}

TEST(Parser, FollowsSpotsPrecedence) {
  const Formula a = atom("a"), b = atom("b"), c = atom("c");
  // & binds tighter than ^, which binds tighter than |, which binds tighter than -> and <->.
  EXPECT_EQ(parse("a | b & c"), Formula::nary(Op::Or, {a, Formula::nary(Op::And, {b, c})}));
  EXPECT_EQ(parse("a ^ b | c"), Formula::nary(Op::Or, {bin(Op::Xor, a, b), c}));
  EXPECT_EQ(parse("a & b ^ c"), bin(Op::Xor, Formula::nary(Op::And, {a, b}), c));
  EXPECT_EQ(parse("a | b -> c"), bin(Op::Implies, Formula::nary(Op::Or, {a, b}), c));
  // -> and <-> share the lowest level and group to the right; ^ groups to the left.
  EXPECT_EQ(parse("a -> b <-> c"), bin(Op::Implies, a, bin(Op::Equiv, b, c)));
  EXPECT_EQ(parse("a <-> b -> c"), bin(Op::Equiv, a, bin(Op::Implies, b, c)));
  EXPECT_EQ(parse("a ^ b ^ c"), bin(Op::Xor, bin(Op::Xor, a, b), c));
  // U R W M bind tighter than & and group to the right; prefix operators bind tighter still.
  EXPECT_EQ(parse("a & b U c"), Formula::nary(Op::And, {a, bin(Op::Until, b, c)}));
  EXPECT_EQ(parse("a U b R c"), bin(Op::Until, a, bin(Op::Release, b, c)));
  EXPECT_EQ(parse("!a U b"), bin(Op::Until, un(Op::Not, a), b));
  EXPECT_EQ(parse("F a U X b"), bin(Op::Until, un(Op::Finally, a), un(Op::Next, b)));
  EXPECT_EQ(parse("a W b M c"), bin(Op::WeakUntil, a, bin(Op::StrongRelease, b, c)));
}

TEST(Parser, AcceptsEverySpellingOfEachOperator) {
  EXPECT_EQ(parse("a && b || !c"), parse("a & b | ! c"));
  EXPECT_EQ(parse("a => b <=> c"), parse("a -> b <-> c"));
  EXPECT_EQ(parse("<> a & [] b"), parse("F a & G b"));
  EXPECT_EQ(parse("\u25C7 a \u2227 \u25A1 b \u2228 \u25CB \u00AC c"), parse("F a & G b | X !c"));
  EXPECT_EQ(parse("a \u2192 b \u2194 c"), parse("a -> b <-> c"));
  EXPECT_EQ(parse("1 & true | 0 | false"), parse("true & true | false | false"));
}

TEST(Parser, ReadsIdentifiersAndQuotedAtoms) {
  EXPECT_EQ(parse("kitchen U pi_3"), bin(Op::Until, atom("kitchen"), atom("pi_3")));
  EXPECT_EQ(parse("\"room 2\" & \"G\""), Formula::nary(Op::And, {atom("room 2"), atom("G")}));
  EXPECT_EQ(parse("Kitchen"), atom("Kitchen"));
  EXPECT_EQ(parse("_x1"), atom("_x1"));
}

TEST(Parser, SplitsLeadingTemporalLettersLikeSpot) {
  EXPECT_EQ(parse("GFa"), un(Op::Globally, un(Op::Finally, atom("a"))));
  EXPECT_EQ(parse("Xp1"), un(Op::Next, atom("p1")));
  EXPECT_EQ(parse("FOO"), atom("FOO"));
  EXPECT_EQ(parse("\"Fridge\""), atom("Fridge"));
}

// BODY@REGION is one atom, read before Spot's splitting, and the same atom as its quoted spelling.
TEST(Parser, ReadsAnObjectAtomWholeBeforeSplittingTemporalLetters) {
  EXPECT_EQ(parse("F crate@dock"), un(Op::Finally, atom("crate@dock")));
  EXPECT_EQ(parse("Fridge@kitchen"), atom("Fridge@kitchen"));
  EXPECT_EQ(parse("\"crate@dock\""), atom("crate@dock"));
  EXPECT_EQ(parse("F(B1@bay1&F B2@bay2)"),
            un(Op::Finally, Formula::nary(Op::And, {atom("B1@bay1"), un(Op::Finally, atom("B2@bay2"))})));
  EXPECT_EQ(to_string(parse("F(Fridge@kitchen & \"big crate@dock\")")), "F(Fridge@kitchen & \"big crate@dock\")");
}

TEST(Parser, NamesWhatIsWrongWithAnObjectAtom) {
  const auto message = [](const char* text) {
    try {
      parse(text);
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("F crate@"), "column 9: expected a region's name after '@', but found the end");
  EXPECT_EQ(message("F crate@1"), "column 9: expected a region's name after '@', but found '1'");
  EXPECT_EQ(message("F a@b@c"), "column 6: an atom names one body and one region (BODY@REGION), but this one holds '@' twice");
  EXPECT_EQ(message("F @dock"), "column 3: unexpected '@'");
  EXPECT_EQ(message("\"a@b@c\""),
            "column 1: an atom names one body and one region (BODY@REGION), but 'a@b@c' holds '@' twice");
  EXPECT_EQ(message("\"@dock\""), "column 1: expected a body's name before '@' in '@dock'");
}

TEST(Parser, FlattensConjunctionsAndDisjunctions) {
  EXPECT_EQ(parse("a & (b & c)"), parse("(a & b) & c"));
  EXPECT_EQ(parse("a & (b & c)").children().size(), 3u);
}

TEST(Parser, PrintedFormulasParseBackToTheSameTree) {
  for (const char* text :
       {"a U (b U c)", "(a U b) U c", "!(a & b)", "X(a | b)", "(a -> b) -> c", "a -> (b -> c)", "a ^ (b ^ c)",
        "(a ^ b) ^ c", "F(a U b) R G c", "\"quoted name\" W \"Fa\"", "(a <-> b) & !X c", "G F a",
        "true U !false", "(a | b) M (c & d)", "a & b U c", "(a & b) U c", "!a U b"}) {
    const Formula f = parse(text);
    EXPECT_EQ(parse(to_string(f)), f) << text << " printed as " << to_string(f);
  }
}

TEST(Parser, PrintsMinimalParenthesesButKeepsBooleanMixesReadable) {
  EXPECT_EQ(reprint("((a)) U ((b))"), "a U b");
  EXPECT_EQ(reprint("a U (b U c)"), "a U b U c");
  EXPECT_EQ(reprint("(a U b) U c"), "(a U b) U c");
  EXPECT_EQ(reprint("a | b & c"), "a | (b & c)");
  EXPECT_EQ(reprint("!(a)"), "!a");
  EXPECT_EQ(reprint("F(a)"), "F a");
  EXPECT_EQ(reprint("F(a & b)"), "F(a & b)");
}

struct BadInput {
  const char* text;
  std::uint32_t column;
  const char* expected;  // a piece of the message
};

TEST(Parser, NamesTheColumnAndWhatWasExpected) {
  for (const BadInput& bad : std::initializer_list<BadInput>{
           {"", 1, "expected a formula"},
           {"a &", 4, "expected a formula"},
           {"F(a & (b", 9, "expected ')' to close the '(' at column 7"},
           {"a b", 3, "expected a binary operator or the end of the formula"},
           {"a)", 2, "no matching '('"},
           {"a # b", 3, "unexpected '#'"},
           {"a - b", 3, "expected '->'"},
           {"\"open", 1, "expected '\"' to close"},
           {"\"\"", 1, "expected a name between the quotes"},
           {"12", 1, "expected 0, 1 or a name"},
           {"\u25C7 \u2203", 3, "unexpected '\u2203'"},  // columns count characters, not bytes
           {"U a", 1, "found 'U'"},
       }) {
    try {
      parse(bad.text);
      ADD_FAILURE() << "no error for " << bad.text;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.column(), bad.column) << bad.text << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(bad.expected), std::string::npos) << bad.text << ": " << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("column " + std::to_string(bad.column) + ": ", 0), 0u) << e.what();
    }
  }
}

TEST(Parser, RefusesNestingDeeperThanTheLimitInsteadOfOverflowingTheStack) {
  const std::string parens = std::string(100000, '(') + "a" + std::string(100000, ')');
  EXPECT_THROW(parse(parens), ParseError);
  std::string chain = "a";
  for (int i = 0; i < 5000; ++i) chain += " U a";
  EXPECT_THROW(parse(chain), ParseError);
  EXPECT_THROW(parse(std::string(5000, '!') + "a"), ParseError);
  // Long flat conjunctions are fine: they do not nest.
  std::string wide = "a";
  for (int i = 0; i < 5000; ++i) wide += " & a";
  EXPECT_NO_THROW(parse(wide));
}

TEST(Parser, ReportsInvalidUtf8AsBytes) {
  try {
    parse("a & \xff");
    ADD_FAILURE();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.column(), 5u);
    EXPECT_NE(std::string(e.what()).find("byte 0xFF"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace physltl::ltl
