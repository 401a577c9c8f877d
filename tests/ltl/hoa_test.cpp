#include "physltl/ltl/hoa.h"
#include "physltl/ltl/parser.h"
#include "physltl/ltl/translate.h"

#include <gtest/gtest.h>

#include <sstream>

namespace physltl::ltl {
namespace {

std::string hoa(const char* text) {
  std::ostringstream out;
  write_hoa(out, translate(parse(text)));
  return out.str();
}

TEST(Hoa, WritesADeterministicStateBasedBuchiAutomatonAsSpotDoes) {
  EXPECT_EQ(hoa("!p3 U p1"),
            "HOA: v1\n"
            "States: 3\n"
            "Start: 0\n"
            "AP: 2 \"p3\" \"p1\"\n"
            "acc-name: Buchi\n"
            "Acceptance: 1 Inf(0)\n"
            "properties: trans-labels explicit-labels state-acc deterministic complete\n"
            "--BODY--\n"
            "State: 0\n"
            "[!0&!1] 0\n"
            "[1] 1\n"
            "[0&!1] 2\n"
            "State: 1 {0}\n"
            "[t] 1\n"
            "State: 2\n"
            "[t] 2\n"
            "--END--\n");
}

TEST(Hoa, LabelsADisjunctionByOneCubePerRegion) {
  const std::string text = hoa("F p1 | F p2 | F p3");
  EXPECT_NE(text.find("[!0&!1&!2] 0\n[0 | 1 | 2] 1\n"), std::string::npos) << text;
}

TEST(Hoa, EscapesQuotesAndBackslashesInPropositionNames) {
  EXPECT_NE(hoa("F \"a\\b\"").find("AP: 1 \"a\\\\b\""), std::string::npos);
}

}  // namespace
}  // namespace physltl::ltl
