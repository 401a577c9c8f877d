#include "cli/command.h"
#include "cli/number_args.h"
#include "physltl/setup/scenario_settings.h"
#include "scenario_test/junit_report.h"
#include "scenario_test/scenario_cases.h"
#include "scenario_test/schedule.h"
#include "scenario_test/summary.h"
#include "scenario_test/test_entries.h"
#include "physltl/common/stop_signal.h"
#include "physltl/common/output_paths.h"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace physltl::app {
namespace {

using namespace scenario_test;

struct TestArgs {
  std::vector<std::string> paths;
  std::optional<std::string> goldens;
  bool update = false;
  std::optional<std::string> junit;
  int jobs = 1;
  std::string out_dir = "out";
};

// Two entries writing one goldens folder would overwrite each other's goldens.
void refuse_shared_goldens(const std::vector<TestEntry>& entries, const TestSettings& settings) {
  std::map<std::filesystem::path, std::string> first_of;
  for (const TestEntry& e : entries) {
    const auto [it, fresh] = first_of.emplace(std::filesystem::weakly_canonical(goldens_folder(e, settings)), e.label);
    if (!fresh) {
      throw common::BadInput("'" + e.label + "' and '" + it->second + "' would share the goldens folder " +
                     goldens_folder(e, settings).string());
    }
  }
}

// `inputs` and the files inside the folders among them (the goldens): a file named by --junit must be none.
std::vector<std::filesystem::path> with_golden_files(std::vector<std::filesystem::path> inputs) {
  const std::size_t named = inputs.size();
  for (std::size_t i = 0; i < named; ++i) {
    std::error_code error;
    if (!std::filesystem::is_directory(inputs[i], error)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(inputs[i], error)) inputs.push_back(entry.path());
  }
  return inputs;
}

int run_tests(const TestArgs& args) {
  const auto started = std::chrono::steady_clock::now();
  common::checked_output_folder("--out", args.out_dir, {});
  const std::vector<TestEntry> entries = expand_test_paths(args.paths);
  TestSettings settings;
  if (args.goldens) settings.goldens_dir = *args.goldens;
  settings.out_dir = std::filesystem::path(args.out_dir) / "test";
  settings.update = args.update;
  settings.stop = &common::stop_flag();
  refuse_shared_goldens(entries, settings);
  // A goldens folder under a regular file can be neither read nor written (--update): said once, up front.
  for (const TestEntry& entry : entries) {
    common::checked_output_folder(args.goldens ? "--goldens" : "goldens folder", goldens_folder(entry, settings).string(), {});
  }
  const std::filesystem::path times = settings.out_dir / "times.json";
  // Every scenario is loaded before any is run: a bad one (an unknown expectation key) stops the command
  // with its file:line before anything is planned or written.
  std::vector<scenario::World> worlds;
  for (const TestEntry& entry : entries) worlds.push_back(setup::load_with_settings(entry.file.string(), entry.settings));
  // What the command reads: the scenarios, their modules and meshes, and the goldens. No output may
  // replace one, and no folder of mismatch pictures may hold one (`--goldens o/test --out o`).
  std::vector<std::filesystem::path> inputs{times};
  for (std::size_t i = 0; i < entries.size(); ++i) {
    inputs.push_back(entries[i].file);
    inputs.insert(inputs.end(), worlds[i].inputs.begin(), worlds[i].inputs.end());
    inputs.push_back(goldens_folder(entries[i], settings));
  }
  for (const TestEntry& entry : entries) common::check_replaceable(settings.out_dir / entry.output_name, inputs);
  std::optional<std::filesystem::path> junit;
  if (args.junit) junit = common::checked_output_file("--junit", *args.junit, with_golden_files(inputs));

  std::vector<ScenarioResult> results(entries.size());
  const std::vector<std::size_t> order = longest_first(entries, worlds, times);
  std::atomic<std::size_t> next{0};
  std::mutex print;
  const auto work = [&] {
    for (std::size_t n = next++; n < entries.size() && !common::stop_received(); n = next++) {
      const std::size_t i = order[n];
      results[i] = test_scenario(entries[i], worlds[i], settings);
      const std::lock_guard<std::mutex> lock(print);
      print_scenario(std::cout, results[i]);
      std::cout.flush();
    }
  };
  std::vector<std::thread> workers;
  for (int j = 1; j < std::min<int>(args.jobs, static_cast<int>(entries.size())); ++j) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();
  if (common::stop_received()) {
    std::cerr << "physltl-studio: interrupted; no summary or JUnit file written\n";
    return common::kExitInterrupted;
  }
  record_times(results, times);
  print_summary(std::cout, results, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  if (junit) {
    write_junit(results, *junit);
    std::cout << "junit      " << junit->string() << "\n";
  }
  for (const ScenarioResult& r : results) {
    if (!r.passed()) return common::kExitNoPlan;
  }
  return common::kExitOk;
}

}  // namespace

CommandRunner add_test_command(CLI::App& app) {
  auto args = std::make_shared<TestArgs>();
  app.add_option("paths", args->paths,
                 "Scenario files, folders of them, or FILE::key=value::... entries with settings for the script's params")
      ->required();
  app.add_option("--goldens", args->goldens,
                 "Folder of the goldens, <DIR>/<scenario>/... (default: goldens/ beside each scenario)");
  app.add_flag("--update", args->update,
               "Write the goldens that are missing or differ beyond their tolerance, and list them");
  app.add_option("--junit", args->junit, "Also write a JUnit XML report to this file");
  app.add_option("--jobs", args->jobs, "Scenarios tested at once, each with one planning thread (same results)")
      ->check(whole_in(1, 64))
      ->capture_default_str();
  app.add_option("--out", args->out_dir, "Folder for outputs; a mismatch leaves its pictures in <out>/test/<scenario>/")
      ->capture_default_str();
  app.footer(
      "\nExit codes: 0 all passed, 1 a test failed, 2 bad input (a scenario or an expectation), 130 interrupted.\n"
      "Expectations, goldens and a CI recipe: docs/testing.md.");
  return [args] { return run_tests(*args); };
}

}  // namespace physltl::app
