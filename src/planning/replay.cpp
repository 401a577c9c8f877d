#include "physltl/planning/replay.h"

#include "physltl/knowledge/kappa.h"
#include "physltl/physics/simulation.h"

#include <fmt/format.h>

namespace physltl::planning {

Replay replay(const scenario::World& world, const Plan& plan, const TaskAutomaton& formula,
              const knowledge::AbstractKnowledge& knowledge, knowledge::ValidityMode mode) {
  Replay r;
  physics::Simulation simulation(world);
  const RegionMap regions(world);
  std::vector<scenario::RobotContact> contacts;
  auto record = [&](int automaton_state, bool pushing) {
    r.states.push_back(simulation.environment());
    r.region_trace.push_back(regions.at(r.states.back().robot_position));
    r.automaton_trace.push_back(formula.step(automaton_state, r.region_trace.back()));
    r.pushing.push_back(pushing);
  };
  record(formula.dfa.start, false);
  knowledge::Kappa kappa = knowledge::infer(knowledge, r.states.back());
  r.reproduces_plan = plan.states.size() == plan.controls.size();
  r.valid = true;
  for (size_t c = 0; c < plan.controls.size(); ++c) {
    bool pushed = false;
    for (int s = 0; s < plan.controls[c].steps; ++s) {
      simulation.step(plan.controls[c].force, contacts);
      bool touching_movable = false;
      for (const auto& contact : contacts) touching_movable |= contact.body == scenario::RobotContact::Body::kMovable;
      pushed |= touching_movable;
      record(r.automaton_trace.back(), touching_movable);
      const auto validity = knowledge::check_validity(knowledge, kappa, r.states.back(), contacts, mode);
      if (!validity.valid() && r.valid) {
        r.valid = false;
        r.failure = fmt::format("step {} (control {}): {}", r.states.size() - 1, c, knowledge::violation_name(validity.violation));
      }
      knowledge::infer(knowledge, r.states.back(), kappa);
    }
    r.pushes += pushed;
    if (r.reproduces_plan && !(simulation.save() == plan.states[c])) {
      r.reproduces_plan = false;
      if (r.failure.empty()) r.failure = fmt::format("control {} ends in a different state than planned", c);
    }
  }
  r.accepted = formula.dfa.accepting[r.automaton_trace.back()];
  if (!r.accepted && r.failure.empty()) r.failure = "the region trace does not satisfy the formula";
  return r;
}

std::vector<std::string> region_names(const scenario::World& world, const std::vector<int>& region_trace) {
  std::vector<std::string> names;
  names.reserve(region_trace.size());
  for (int r : region_trace) names.push_back(r < 0 ? "p0" : world.regions[r].name);
  return names;
}

}  // namespace physltl::planning
