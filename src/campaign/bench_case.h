#pragma once
// The cases of a campaign loaded: one World per scenario entry and swept value, reasoned about and
// prepared for the planners once, with the facts bench reports about it (campaign.h).

#include "units.h"
#include "unit_record.h"

#include "physltl/campaign/campaign.h"

#include "physltl/planning/planning_problem.h"
#include "physltl/scenario/world.h"
#include "physltl/setup/run_settings.h"

#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace physltl::campaign {

struct BenchCase {
  size_t entry = 0;         // the scenario entry it comes from
  std::string swept_value;  // empty unless the entry sweeps
  scenario::World world;
  setup::RunSettings settings;  // the World's with the campaign's flags; its seed is the case's first
  std::unique_ptr<planning::PlanningProblem> problem;  // of `world`
  BenchResults results;  // the case's facts, and its planners without runs yet
};

// Loads every case before any run, so a bad value fails at once. Throws BadInput, ScenarioError or
// InfeasibleTask. Every value of an entry runs on the same seeds (--seed, or the first value's scenario
// seed), even if a script chose its default seed by its params.
std::vector<std::unique_ptr<BenchCase>> load_cases(const std::vector<ScenarioEntry>& entries,
                                                   const CampaignSettings& settings);

// A sweep's peak memory: for every swept case and planner, the first seed's run again as the main job in
// a process of its own (PlannerRuns::own_process). Throws Interrupted on Ctrl-C.
void run_sweeps_in_own_processes(const std::vector<ScenarioEntry>& entries, const CampaignSettings& settings,
                                 const std::vector<std::unique_ptr<BenchCase>>& cases);

// The cases as the campaign's units see them.
std::vector<CaseUnits> case_units(const std::vector<std::unique_ptr<BenchCase>>& cases);

// The cases with the runs of `records` (by canonical unit index) in their planners, in unit order; each
// case's total duration is the sum of its units' times. Host and CPU are this machine's.
CampaignResults collect_results(const std::vector<ScenarioEntry>& entries,
                                const std::vector<std::unique_ptr<BenchCase>>& cases, const std::vector<Unit>& units,
                                const std::map<size_t, UnitRecord>& records);

// One unit: plans and validates, timing the search apart from the improvement `settings` ask for; with
// robustness_worlds > 0, a solved plan is replayed in as many worlds drawn from the settings' uncertainty
// (seeded by the run's seed).
BenchRun measure(const planning::PlanningProblem& problem, const planning::PlannerEntry& planner,
                 const setup::RunSettings& settings, const planning::PlannerOptions& options, int robustness_worlds = 0);

}  // namespace physltl::campaign
