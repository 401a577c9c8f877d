#pragma once
// The cases of one scenario, in the order docs/testing.md gives: check, the main job's plan and its
// bounds, plan.json against its golden, then the pictures.

#include "case_result.h"
#include "test_entries.h"
#include "physltl/scenario/world.h"

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>

namespace physltl::app::scenario_test {

struct TestSettings {
  std::optional<std::filesystem::path> goldens_dir;  // unset: beside each scenario, <dir>/goldens/
  std::filesystem::path out_dir = "out/test";        // <out_dir>/<name>/: what a mismatch leaves
  bool update = false;
  const std::atomic<bool>* stop = nullptr;           // Ctrl-C: the scenario ends as interrupted
};

std::filesystem::path goldens_folder(const TestEntry& entry, const TestSettings& settings);
// The command a user runs to write this entry's goldens.
std::string update_line(const TestEntry& entry, const TestSettings& settings);

// One planning thread, the main job's seed, time limit and plan improvement: the plan the main job writes.
ScenarioResult test_scenario(const TestEntry& entry, const scenario::World& world, const TestSettings& settings);

}  // namespace physltl::app::scenario_test
