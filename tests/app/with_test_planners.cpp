// physltl-studio with three planners added through the registry, as a lab would add its own: nothing in
// src/app or in the planning core knows them (registry_cli_test.cpp runs this program).

#include "cli/command_line.h"

#include "physltl/planners/registry.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace {

using namespace physltl::planning;

// What test-annotated keeps of its own: the flavour it was given, and whether it prepared the problem.
struct Annotation : PlannerData {
  std::string flavour;
  bool prepared = false;
  long long propagations = 0;
};

// The baseline's search with a parameter of its own (--test-flavour) and data of its own: a line before
// the search, a key in report.json.
PlannerEntry annotated(const PlannerEntry& baseline) {
  PlannerEntry entry;
  entry.name = "test-annotated";
  entry.summary = "the baseline with a parameter and report data of its own (a test's)";
  entry.can = baseline.can;
  entry.uses_knowledge = false;
  entry.parameters = {{"test-flavour", "A parameter of the test's planner: plain or salted", {"plain", "salted"},
                       [](const std::string& value) { return value == "salted" ? "the test's planner was salted" : ""; }}};
  entry.report_keys = {"test_note"};
  entry.prepare = [](const Problem&, const physltl::planning::PreparationOptions&) {
    auto prepared = std::make_shared<Annotation>();
    prepared->prepared = true;
    return prepared;
  };
  entry.plan = [&baseline, flavour = entry.parameters.front()](const Problem& problem, const PlannerData* prepared,
                                                                const PlannerOptions& options) {
    PlanResult result = baseline.plan(problem, nullptr, options);
    auto note = std::make_shared<Annotation>();
    note->flavour = options.parameter(flavour);
    note->prepared = prepared != nullptr && dynamic_cast<const Annotation&>(*prepared).prepared;
    note->propagations = result.stats.propagations;
    result.own = std::move(note);
    return result;
  };
  entry.account = [](const PlannerData& data, const physltl::scenario::World&) {
    const auto& note = dynamic_cast<const Annotation&>(data);
    PlannerAccount account;
    if (note.flavour.empty()) {
      account.lines.push_back("test-note  prepared");
    } else {
      account.report["test_note"] = {{"flavour", note.flavour}, {"prepared", note.prepared}, {"propagations", note.propagations}};
    }
    return account;
  };
  return entry;
}

}  // namespace

int main(int argc, char** argv) {
  PlannerRegistry& registry = physltl::planners::registry();
  const PlannerEntry& baseline = registry.reference_planner();
  // The baseline's search under another name: it can take everything the baseline can.
  PlannerEntry same = baseline;
  same.name = "test-planner";
  same.summary = "the baseline under another name (a test's)";
  registry.add(std::move(same));
  // One that reads the robot's region only, like OMPL's product, and has no budget.
  PlannerEntry robot_only = baseline;
  robot_only.name = "test-robot-only";
  robot_only.summary = "the baseline, refusing tasks about bodies (a test's)";
  robot_only.can.object_tasks = {false, "this test's planner reads the robot's region only"};
  robot_only.can.propagation_budget = {false, "this test's planner stops at a time limit only"};
  registry.add(std::move(robot_only));
  registry.add(annotated(baseline));
  // One whose search fails as a fault of ours would: the program must say it is an internal error.
  PlannerEntry throws = baseline;
  throws.name = "test-throws";
  throws.summary = "a planner that throws (a test's)";
  throws.plan = [](const Problem&, const PlannerData*, const PlannerOptions&) -> PlanResult {
    throw std::logic_error("the test's planner failed on purpose");
  };
  registry.add(std::move(throws));
  return physltl::app::run_command_line(argc, argv);
}
