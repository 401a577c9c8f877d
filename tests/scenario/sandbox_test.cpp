// The Lua sandbox: what a script may do, and what it may not.

#include "physltl/scenario/load.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace physltl::scenario {
namespace {

class Sandbox : public testing::Test {
 protected:
  std::string write(const std::string& text) {
    const auto dir = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / "sandbox";
    std::filesystem::create_directories(dir);
    const auto path = dir / (std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) + ".lua");
    std::ofstream(path) << text;
    return path.string();
  }

  // Its task names no region, so a test may add whichever regions it likes.
  static std::string minimal_world(const std::string& extra) {
    return "workspace { bounds = { { 0, 0 }, { 10, 10 } } }\n"
           "robot { start = { 1, 1 } }\n"
           "task { formula = 'F true' }\n" + extra;
  }

  static std::string first_message(const std::string& path, const LoadOptions& options = {}) {
    try {
      load_scenario(path, options);
    } catch (const ScenarioError& e) {
      return e.diagnostics().front().str();
    }
    return "accepted";
  }
};

TEST_F(Sandbox, ParamsFromTheCommandLineReachTheScript) {
  const std::string path = write(minimal_world(
      "for i = 1, params.regions do region { name = 'p' .. i, rect = { { i, 5 }, { i + 0.5, 6 } } } end\n"
      "assert(params.label == 'wide')\n"));
  LoadOptions options;
  options.params = {{"regions", "3"}, {"label", "wide"}};
  EXPECT_EQ(load_scenario(path, options).regions.size(), 3u);
}

TEST_F(Sandbox, ASettingNoScriptReadsIsAnErrorNamingItAndWhatIsRead) {
  const std::string path = write(minimal_world("local n = params.boxes or 4\nlocal w = params.width\n"));
  LoadOptions options;
  options.params = {{"boxs", "6"}, {"width", "2"}};
  EXPECT_EQ(first_message(path, options),
            path + ": the setting boxs=6 is read by no script: did you mean 'boxes'? the scenario reads params boxes, width");
  options.params = {{"boxes", "6"}};
  EXPECT_EQ(first_message(path, options), "accepted");
}

TEST_F(Sandbox, ASettingTheScriptOverwritesBeforeReadingIsUnreadButOneWalkedWithPairsIsRead) {
  const std::string overwritten = write(minimal_world("params.drive = 'differential'\nlocal d = params.drive\n"));
  LoadOptions options;
  options.params = {{"drive", "car"}};
  EXPECT_NE(first_message(overwritten, options).find("the setting drive=car is read by no script"), std::string::npos);
  const std::string walked = write(minimal_world("for k, v in pairs(params) do assert(k == 'drive' and v == 'car') end\n"));
  EXPECT_EQ(first_message(walked, options), "accepted");
}

TEST_F(Sandbox, UndefinedVariablesAreErrorsWhereTheyAreReadButRawgetMayProbeForThem) {
  const std::string path = write(minimal_world("local size = 0.5\nlocal s = sise\n"));
  EXPECT_EQ(first_message(path), path + ":5: undefined variable 'sise' (did you mean 'size'?)");
  const std::string probing = write(minimal_world("if rawget(_G, 'optional') == nil then made = 1 end\nlocal m = made\n"));
  EXPECT_EQ(first_message(probing), "accepted");
  const std::string sandboxed = write(minimal_world("os.exit(1)\n"));
  EXPECT_NE(first_message(sandboxed).find(":4: global 'os' is not available to scenarios"), std::string::npos);
}

TEST_F(Sandbox, MathRandomGivesTheSameWorldEveryTime) {
  const std::string path = write(minimal_world(
      "movable { name = 'B', center = { 2 + 6 * math.random(), 2 + 6 * math.random() }, size = { 0.5, 0.5 } }\n"));
  const Vec2 a = load_scenario(path).movable_bodies[0].footprint.pose.position;
  const Vec2 b = load_scenario(path).movable_bodies[0].footprint.pose.position;
  EXPECT_EQ(a, b);
}

TEST_F(Sandbox, EveryProblemInAFileIsReportedTogether) {
  const std::string path = write(minimal_world(
      "movable { name = 'B', center = { 3, 3 }, size = { 0.5, 0.5 }, mas = 1 }\n"
      "region { name = 'p1', rect = { { 5, 5 }, { 6, 6 } }, colour = 'red' }\n"));
  try {
    load_scenario(path);
    FAIL();
  } catch (const ScenarioError& e) {
    ASSERT_EQ(e.diagnostics().size(), 2u) << e.what();
    EXPECT_EQ(e.diagnostics()[0].where.line, 4);
    EXPECT_NE(e.diagnostics()[0].message.find("did you mean 'mass'"), std::string::npos);
    EXPECT_EQ(e.diagnostics()[1].where.line, 5);
  }
}

TEST_F(Sandbox, InstructionBudgetStopsAnEndlessLoopQuickly) {
  const std::string path = write(minimal_world("local i = 0\nwhile true do i = i + 1 end\n"));
  LoadOptions options;
  options.instruction_budget = 1'000'000;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(first_message(path, options), path + ":5: instruction budget of 1000000 exceeded (an endless loop?)");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST_F(Sandbox, MemoryCapStopsAHugeTable) {
  const std::string path = write(minimal_world("local t = {}\nfor i = 1, 1e8 do t[i] = i end\n"));
  LoadOptions options;
  options.memory_limit_bytes = 8u << 20;
  EXPECT_NE(first_message(path, options).find("memory limit of 8 MiB exceeded"), std::string::npos);
}

// Variants of a world share its file: `require` finds a module beside the scenario after the helpers.
TEST_F(Sandbox, AScenarioRequiresAModuleBesideItAfterTheHelpers) {
  const std::string shared = write(minimal_world("region { name = 'shared', rect = { { 5, 5 }, { 6, 6 } } }\n"));
  const std::string stem = std::filesystem::path(shared).stem().string();
  const auto variant = std::filesystem::path(shared).parent_path() / "variant.lua";
  std::ofstream(variant) << "params.anything = 1\nrequire '" << stem << "'\n";
  const World world = load_scenario(variant.string());
  ASSERT_EQ(world.regions.size(), 1u);
  EXPECT_EQ(world.regions[0].name, "shared");
  EXPECT_EQ(world.regions[0].where.file, shared);  // the line is the shared file's
}

TEST_F(Sandbox, HelpersAreRequiredByModuleNameOnly) {
  EXPECT_EQ(load_scenario(write(minimal_world("local P = require 'physltl'\nP.box { name = 'B', at = { 3, 3 } }\n")))
                .movable_bodies.size(),
            1u);
  EXPECT_NE(first_message(write(minimal_world("require '/etc/passwd'\n"))).find("not a helper module name"),
            std::string::npos);
}

TEST_F(Sandbox, RuntimeErrorsNameTheWholePathHoweverLong) {
  const std::string path = write(minimal_world("local x = nil + 1\n"));
  ASSERT_GT(path.size(), 60u);  // Lua's own messages keep "..." and the last 56 characters
  const std::string message = first_message(path);
  EXPECT_EQ(message.rfind(path + ":4: ", 0), 0u) << message;
}

TEST_F(Sandbox, MissingScenarioFileIsAClearError) {
  EXPECT_EQ(first_message("no/such/file.lua"),
            "no/such/file.lua: no such file");
}

}  // namespace
}  // namespace physltl::scenario
