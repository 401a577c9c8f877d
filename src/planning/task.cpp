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

RegionMap::RegionMap(const scenario::World& world) : world_(world) {
  for (const auto& region : world.regions) bounds_.push_back(region.polygon.bounds());
}

int RegionMap::at(const scenario::Vec2& p) const {
  for (size_t i = 0; i < bounds_.size(); ++i) {
    if (bounds_[i].contains(p) && world_.regions[i].polygon.contains(p)) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace physltl::planning
