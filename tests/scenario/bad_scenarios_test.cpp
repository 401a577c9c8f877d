// Table-driven: each file in tests/bad_scenarios/ makes one mistake and names, on its first line,
// the diagnostic it must produce:  -- expect: LINE: text the message contains

#include "bad_scenario_files.h"
#include "physltl/scenario/load.h"

#include <gtest/gtest.h>

namespace physltl::scenario {
namespace {

using testing_support::bad_scenario_files;

class BadScenario : public testing::TestWithParam<std::string> {};

TEST_P(BadScenario, IsRefusedWithTheExpectedFileLineAndMessage) {
  const std::string path = GetParam();
  const auto expected = testing_support::expected_diagnostic(path);
  ASSERT_TRUE(expected) << path << ": bad header";
  try {
    load_scenario(path);
    FAIL() << path << " was accepted";
  } catch (const ScenarioError& e) {
    bool found = false;
    for (const auto& d : e.diagnostics()) {
      found = found || (d.where.file == path && d.where.line == expected->line &&
                        d.message.find(expected->text) != std::string::npos);
    }
    EXPECT_TRUE(found) << "expected " << path << ":" << expected->line << ": ..." << expected->text << "\ngot:\n"
                       << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Files, BadScenario, testing::ValuesIn(bad_scenario_files()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return testing_support::bad_scenario_name(info.param);
                         });

TEST(BadScenarios, TheFolderHoldsAtLeastThirtyMistakes) { EXPECT_GE(bad_scenario_files().size(), 30u); }

}  // namespace
}  // namespace physltl::scenario
