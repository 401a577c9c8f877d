#pragma once
// The settings of one run, made once per command from what the scenario's planner { }, uncertainty { } and
// render { } say and the flags that replace them; run, execute, test and bench all plan with them, and the
// World stays what its file says. Where the scenario says nothing, every command starts from the same
// defaults (run_settings), and each command that departs from them says so where it sets its flags:
//   - threads: 1; the main job takes one per core (same plan, sooner), bench the --threads list.
//   - improvement: default_improvement_candidates(world) for run and test; bench spends --improve only (it
//     times the search), execute none (it executes and replans the search's plans as found).

#include "physltl/base/deadline.h"
#include "physltl/planning/planner_options.h"
#include "physltl/planning/validation/validated_plan.h"
#include "physltl/scenario/world.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace physltl::setup {

struct RunSettings {
  std::uint64_t seed = 1;
  double time_limit_s = scenario::kDefaultTimeLimit;  // of the whole run, from its start
  int threads = 1;
  planning::ImprovementSettings improvement;
  // Values of the planners' own parameters by name (PlannerEntry::parameters); unnamed ones at their defaults.
  std::map<std::string, std::string> parameters;
  scenario::Uncertainty uncertainty;  // what --robustness and execute perturb
  scenario::RenderView view = scenario::RenderView::kPerspective;

  // What a planner takes of them: the seed, the threads, the parameters and `deadline` (the run's, which
  // ends at time_limit_s from the run's start).
  planning::PlannerOptions planner_options(const base::Deadline& deadline) const;
};

// What a command line may set of a run; each flag not given keeps what the scenario says.
struct RunFlags {
  std::optional<std::uint64_t> seed{};
  std::optional<double> time_limit_s{};
  std::optional<int> threads{};
  std::optional<int> improve{};             // candidates
  std::optional<double> improve_for_s{};    // seconds of improvement instead (the plan then depends on the machine)
  std::optional<std::string> cost{};        // as --cost writes it: "time", "time + 2 pushes"
  std::optional<double> improve_margin_m{};
  std::optional<std::string> uncertainty{};  // as --uncertainty writes it: "mass=0.3,friction=0.1"
  std::optional<scenario::RenderView> view{};
  std::map<std::string, std::string> parameters{};
};

// The run's settings: `world`'s, with `flags` replacing them. Throws BadInput for a cost or uncertainty the
// flags misspell.
RunSettings run_settings(const scenario::World& world, const RunFlags& flags);

}  // namespace physltl::setup
