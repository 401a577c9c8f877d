// Table-driven: each file in tests/bad_scenarios/ makes one mistake and names, on its first line,
// the diagnostic it must produce:  -- expect: LINE: text the message contains

#include "physltl/scenario/load.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

namespace physltl::scenario {
namespace {

std::vector<std::string> bad_scenario_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(PHYSLTL_SOURCE_DIR) + "/tests/bad_scenarios")) {
    if (e.path().extension() == ".lua") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class BadScenario : public testing::TestWithParam<std::string> {};

TEST_P(BadScenario, IsRefusedWithTheExpectedFileLineAndMessage) {
  const std::string path = GetParam();
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  std::smatch m;
  ASSERT_TRUE(std::regex_match(header, m, std::regex("-- expect: (\\d+): (.*)"))) << path << ": bad header";
  const int line = std::stoi(m[1]);
  const std::string text = m[2];
  try {
    load_scenario(path);
    FAIL() << path << " was accepted";
  } catch (const ScenarioError& e) {
    bool found = false;
    for (const auto& d : e.diagnostics()) {
      found = found || (d.where.file == path && d.where.line == line && d.message.find(text) != std::string::npos);
    }
    EXPECT_TRUE(found) << "expected " << path << ":" << line << ": ..." << text << "\ngot:\n" << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Files, BadScenario, testing::ValuesIn(bad_scenario_files()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return std::filesystem::path(info.param).stem().string();
                         });

TEST(BadScenarios, TheFolderHoldsAtLeastThirtyMistakes) { EXPECT_GE(bad_scenario_files().size(), 30u); }

}  // namespace
}  // namespace physltl::scenario
