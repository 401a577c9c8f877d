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

bool Labelling::NamedPart::has_body(int body) const { return std::find(bodies.begin(), bodies.end(), body) != bodies.end(); }

int Labelling::NamedPart::place_of_region(int region) const {
  for (std::size_t k = 0; k < region_sets.size(); ++k) {
    if (std::find(region_sets[k].begin(), region_sets[k].end(), region) != region_sets[k].end()) return static_cast<int>(k) + 1;
  }
  return 0;
}

Labelling::Labelling(const scenario::World& world, const ltl::Dfa& dfa)
    : map_(world), regions_count_(static_cast<int>(world.regions.size())), proposition_names_(dfa.propositions) {
  for (const auto& region : world.regions) robot_proposition_.push_back(dfa.proposition_index(region.name));
  for (int p = 0; p < static_cast<int>(dfa.propositions.size()); ++p) {
    const auto object = ltl::object_atom(dfa.propositions[static_cast<size_t>(p)]);
    if (!object) continue;
    std::vector<int> bodies = scenario::bodies_named(world, object->body), regions = scenario::regions_named(world, object->region);
    if (bodies.empty() || regions.empty()) {
      // The scenario's validation refuses such formulas; a caller that skipped it gets told, not a crash.
      throw std::invalid_argument("'" + dfa.propositions[static_cast<size_t>(p)] +
                                  "' names no movable body and region of this world");
    }
    auto named = std::find_if(named_.begin(), named_.end(), [&](const NamedPart& n) { return n.name == object->body; });
    if (named == named_.end()) named = named_.insert(named_.end(), NamedPart{object->body, std::move(bodies), {}, {}, {}, 1});
    named->region_sets.push_back(std::move(regions));
    named->set_names.push_back(object->region);
    named->propositions.push_back(p);
  }
  std::sort(named_.begin(), named_.end(), [](const NamedPart& a, const NamedPart& b) { return a.bodies < b.bodies; });
  for (NamedPart& n : named_) {
    n.stride = fact_sets_;
    fact_sets_ *= n.places();
    if (fact_sets_ > kMaxFactSets) {
      // A task the scenario may write but the planner cannot take: the author's to change (exit 2).
      throw scenario::ScenarioError({{world.task.where, "the task names " + std::to_string(named_.size()) + " bodies in " +
                                                            "more places together than the planner can tell apart (over " +
                                                            std::to_string(kMaxFactSets) + "): name fewer bodies or regions, " +
                                                            "or name them together through groups (docs/scenarios.md#groups)"}});
    }
  }
}

int Labelling::part_of(int body) const {
  for (std::size_t i = 0; i < named_.size(); ++i) {
    if (named_[i].has_body(body)) return static_cast<int>(i);
  }
  return -1;
}

int Labelling::place(int facts, int named) const {
  const NamedPart& n = named_[static_cast<size_t>(named)];
  return facts / n.stride % n.places();
}

int Labelling::with_place(int facts, int named, int place) const {
  return facts + (place - this->place(facts, named)) * named_[static_cast<size_t>(named)].stride;
}

int Labelling::facts(const scenario::EnvironmentState& state) const {
  int facts = 0;
  for (const NamedPart& n : named_) {
    int place = -1;  // the place every body so far is in
    for (int body : n.bodies) {
      const int here = n.place_of_region(map_.at(state.movable_poses[static_cast<size_t>(body)].position));
      place = place < 0 || place == here ? here : 0;
      if (place == 0) break;
    }
    facts += std::max(place, 0) * n.stride;
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
