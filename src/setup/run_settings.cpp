#include "physltl/setup/run_settings.h"

#include "physltl/planning/validation/improve.h"
#include "physltl/setup/cost_args.h"
#include "physltl/setup/uncertainty_args.h"

namespace physltl::setup {

planning::PlannerOptions RunSettings::planner_options(const base::Deadline& deadline) const {
  planning::PlannerOptions options;
  options.seed = seed;
  options.deadline = deadline;
  options.threads = threads;
  options.parameters = parameters;
  return options;
}

RunSettings run_settings(const scenario::World& world, const RunFlags& flags) {
  const scenario::PlannerSettings& declared = world.planner;
  RunSettings settings;
  settings.seed = flags.seed.value_or(declared.seed);
  settings.time_limit_s = flags.time_limit_s.value_or(declared.time_limit);
  settings.threads = flags.threads.value_or(1);
  settings.improvement.candidates = flags.improve.value_or(planning::default_improvement_candidates(world));
  settings.improvement.for_s = flags.improve_for_s;
  settings.improvement.cost = flags.cost ? cost_from_flag(*flags.cost) : declared.cost;
  settings.improvement.margin_m = flags.improve_margin_m.value_or(declared.improve_margin);
  settings.parameters = flags.parameters;
  settings.uncertainty = flags.uncertainty ? override_uncertainty(world.uncertainty, *flags.uncertainty) : world.uncertainty;
  settings.view = flags.view.value_or(world.render.view);
  return settings;
}

}  // namespace physltl::setup
