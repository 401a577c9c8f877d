// physltl-studio with two planners added through the registry, as a lab would add its own: nothing in
// src/app knows them (registry_cli_test.cpp runs this program).

#include "command_line.h"

#include "physltl/planning/registry.h"

int main(int argc, char** argv) {
  using namespace physltl::planning;
  PlannerRegistry& registry = PlannerRegistry::instance();
  const PlannerEntry& baseline = registry.reference_planner();
  // The baseline's search under another name: it can take everything the baseline can.
  registry.add({"test-planner", "the baseline under another name (a test's)", baseline.can, false, baseline.plan});
  // One that reads the robot's region only, like OMPL's product, and has no budget.
  Capabilities robot_only = baseline.can;
  robot_only.object_tasks = {false, "this test's planner reads the robot's region only"};
  robot_only.propagation_budget = {false, "this test's planner stops at a time limit only"};
  registry.add({"test-robot-only", "the baseline, refusing tasks about bodies (a test's)", robot_only, false, baseline.plan});
  return physltl::app::run_command_line(argc, argv);
}
