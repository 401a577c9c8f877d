#include "physltl/knowledge/labelling.h"

#include "physltl/ltl/object_atom.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace physltl::knowledge {

RegionMap::RegionMap(const scenario::World& world) : world_(&world) {
  for (const auto& region : world.regions) bounds_.push_back(region.polygon.bounds());
}

int RegionMap::at(const scenario::Vec2& p) const {
  for (size_t i = 0; i < bounds_.size(); ++i) {
    if (bounds_[i].contains(p) && world_->regions[i].polygon.contains(p)) return static_cast<int>(i);
  }
  return -1;
}

Labelling::Labelling(const scenario::World& world, const ltl::Dfa& dfa)
    : map_(world), regions_count_(static_cast<int>(world.regions.size())), proposition_names_(dfa.propositions) {
  for (const auto& region : world.regions) robot_proposition_.push_back(dfa.proposition_index(region.name));
  for (int p = 0; p < static_cast<int>(dfa.propositions.size()); ++p) {
    const auto object = ltl::object_atom(dfa.propositions[static_cast<size_t>(p)]);
    if (!object) continue;
    const int body = scenario::movable_body_index(world, object->body), region = scenario::region_index(world, object->region);
    if (body < 0 || region < 0) {
      // The scenario's validation refuses such formulas; a caller that skipped it gets told, not a crash.
      throw std::invalid_argument("'" + dfa.propositions[static_cast<size_t>(p)] +
                                  "' names no movable body and region of this world");
    }
    auto named = std::find_if(named_.begin(), named_.end(), [&](const NamedBody& n) { return n.body == body; });
    if (named == named_.end()) named = named_.insert(named_.end(), NamedBody{body, {}, {}, 0});
    named->regions.push_back(region);
    named->propositions.push_back(p);
  }
  std::sort(named_.begin(), named_.end(), [](const NamedBody& a, const NamedBody& b) { return a.body < b.body; });
  for (NamedBody& n : named_) {
    n.stride = fact_sets_;
    fact_sets_ *= static_cast<int>(n.regions.size()) + 1;
    if (fact_sets_ > kMaxFactSets) {
      // A task the scenario may write but the planner cannot take: the author's to change (exit 2).
      throw scenario::ScenarioError({{world.task.where, "the task names " + std::to_string(named_.size()) + " bodies in " +
                                                            "more places together than the planner can tell apart (over " +
                                                            std::to_string(kMaxFactSets) + "): name fewer bodies or regions"}});
    }
  }
}

int Labelling::place(int facts, int named) const {
  const NamedBody& n = named_[static_cast<size_t>(named)];
  return facts / n.stride % (static_cast<int>(n.regions.size()) + 1);
}

int Labelling::with_place(int facts, int named, int place) const {
  return facts + (place - this->place(facts, named)) * named_[static_cast<size_t>(named)].stride;
}

int Labelling::facts(const scenario::EnvironmentState& state) const {
  int facts = 0;
  for (const NamedBody& n : named_) {
    const int region = map_.at(state.movable_poses[static_cast<size_t>(n.body)].position);
    const auto k = std::find(n.regions.begin(), n.regions.end(), region);
    if (k != n.regions.end()) facts += (static_cast<int>(k - n.regions.begin()) + 1) * n.stride;
  }
  return facts;
}

int Labelling::letter(const scenario::EnvironmentState& state) const {
  return letter(named_.empty() ? 0 : facts(state), map_.at(state.robot_position));
}

std::vector<int> Labelling::true_propositions(int letter) const {
  std::vector<int> props;
  const int region = robot_region_of(letter);
  if (region >= 0 && robot_proposition_[static_cast<size_t>(region)] >= 0) {
    props.push_back(robot_proposition_[static_cast<size_t>(region)]);
  }
  const int facts = facts_of(letter);
  for (size_t i = 0; i < named_.size(); ++i) {
    const int k = place(facts, static_cast<int>(i));
    if (k > 0) props.push_back(named_[i].propositions[static_cast<size_t>(k - 1)]);
  }
  std::sort(props.begin(), props.end());
  return props;
}

std::vector<std::string> Labelling::object_facts(int facts) const {
  std::vector<std::string> names;
  for (size_t i = 0; i < named_.size(); ++i) {
    const int k = place(facts, static_cast<int>(i));
    if (k > 0) names.push_back(proposition_names_[static_cast<size_t>(named_[i].propositions[static_cast<size_t>(k - 1)])]);
  }
  return names;
}

}  // namespace physltl::knowledge
