#include "physltl/planning/task.h"

#include "physltl/ltl/translate.h"

namespace physltl::planning {

TaskAutomaton TaskAutomaton::make(const ltl::Formula& formula, const scenario::World& world) {
  return make(formula, ltl::translate(formula), world);
}

TaskAutomaton TaskAutomaton::make(const ltl::Formula& formula, const ltl::Dfa& dfa, const scenario::World& world) {
  TaskAutomaton task{formula, dfa, {}, {}};
  for (const auto& region : world.regions) task.proposition_of_region.push_back(dfa.proposition_index(region.name));
  const int letters = static_cast<int>(world.regions.size()) + 1;
  task.successors.resize(dfa.size() * static_cast<size_t>(letters));
  for (int state = 0; state < static_cast<int>(dfa.size()); ++state) {
    for (int region = -1; region + 1 < letters; ++region) {
      const int proposition = region < 0 ? -1 : task.proposition_of_region[region];
      task.successors[state * letters + region + 1] =
          proposition < 0 ? dfa.step(state, {}) : dfa.step(state, std::span<const int>(&proposition, 1));
    }
  }
  return task;
}

int TaskAutomaton::step(int state, int region) const {
  return successors[state * (proposition_of_region.size() + 1) + region + 1];
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
