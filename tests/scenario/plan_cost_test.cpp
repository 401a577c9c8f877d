// What a user may write for a plan's cost (`--cost`, `planner { cost = ... }`), how it is written back, and
// the errors that name what is wrong.

#include "physltl/scenario/plan_cost.h"

#include <gtest/gtest.h>

namespace physltl::scenario {
namespace {

TEST(PlanCost, ByDefaultItIsTheMotionsTime) {
  EXPECT_EQ(PlanCost{}.text(), "time");
  EXPECT_EQ(PlanCost{}.unit(), "s");
}

TEST(PlanCost, ReadsOneMeasureOrAWeightedSum) {
  EXPECT_EQ(parse_plan_cost("pushes"), (PlanCost{0, 0, 1, 0}));
  EXPECT_EQ(parse_plan_cost("time + 2 pushes"), (PlanCost{1, 0, 2, 0}));
  EXPECT_EQ(parse_plan_cost(" 0.5*length+moved "), (PlanCost{0, 0.5, 0, 1}));
  EXPECT_EQ(parse_plan_cost("3 * time"), (PlanCost{3, 0, 0, 0}));
  EXPECT_EQ(parse_plan_cost("1e-1 length"), (PlanCost{0, 0.1, 0, 0}));
}

TEST(PlanCost, WritesItselfBackAsItReads) {
  for (const char* text : {"time", "length", "pushes", "moved", "time + 2 pushes", "0.5 length + moved", "2 time + 0.25 pushes"}) {
    EXPECT_EQ(parse_plan_cost(text).text(), text);
    EXPECT_EQ(parse_plan_cost(parse_plan_cost(text).text()), parse_plan_cost(text));
  }
  EXPECT_EQ(parse_plan_cost("length").unit(), "m");
  EXPECT_EQ(parse_plan_cost("moved").unit(), "bodies");
  EXPECT_EQ(parse_plan_cost("time + pushes").unit(), "");  // a sum has no unit
  EXPECT_EQ(parse_plan_cost("2 time").unit(), "");         // nor a weighted time
}

void expect_refused(const char* text, const std::string& naming) {
  try {
    parse_plan_cost(text);
    ADD_FAILURE() << "'" << text << "' was accepted";
  } catch (const PlanCostError& e) {
    EXPECT_NE(std::string(e.what()).find(naming), std::string::npos) << "'" << text << "': " << e.what();
  }
}

TEST(PlanCost, AMistakeIsRefusedNamingTheToken) {
  expect_refused("tme", "at 'tme'");
  expect_refused("time + psuhes", "at 'psuhes'");
  expect_refused("time pushes", "expected '+' between terms at 'pushes'");
  expect_refused("time +", "at the end");
  expect_refused("-1 time", "a weight must be a number from 0 to 1000000 at '-1'");
  expect_refused("nan time", "at 'nan'");
  // Weights whose costs would be infinite, or past what a campaign reads back.
  expect_refused("1e308 time + 1e308 length", "a weight must be a number from 0 to 1000000 at '1e308'");
  expect_refused("1e20 time", "at '1e20'");
  EXPECT_EQ(parse_plan_cost("1000000 pushes"), (PlanCost{0, 0, 1e6, 0}));
  expect_refused("time + time", "time is named twice");
  expect_refused("0 time", "every weight is 0");
  expect_refused("", "no cost given");
  expect_refused("time * 2", "at '*'");
}

}  // namespace
}  // namespace physltl::scenario
