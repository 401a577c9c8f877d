#include "physltl/planning/task.h"

namespace physltl::planning {

TaskAutomaton TaskAutomaton::make(const ltl::Dfa& dfa, const scenario::World& world) {
  TaskAutomaton task{dfa, {}};
  for (const auto& region : world.regions) task.proposition_of_region.push_back(dfa.proposition_index(region.name));
  return task;
}

int TaskAutomaton::step(int state, int region) const {
  const int proposition = region < 0 ? -1 : proposition_of_region[region];
  if (proposition < 0) return dfa.step(state, {});
  return dfa.step(state, std::span<const int>(&proposition, 1));
}

int region_at(const scenario::World& world, const scenario::Vec2& p) {
  for (size_t i = 0; i < world.regions.size(); ++i) {
    if (world.regions[i].polygon.contains(p)) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace physltl::planning
