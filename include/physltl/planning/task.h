#pragma once
// What the planner must achieve, prepared once per run: the automaton of the (simplified) formula and
// how regions of the World map to its propositions.

#include "physltl/ltl/dfa.h"
#include "physltl/scenario/world.h"

#include <vector>

namespace physltl::planning {

struct TaskAutomaton {
  ltl::Dfa dfa;
  // For each World region, the index of its proposition in dfa.propositions, or -1 when the formula
  // does not mention it (the region then reads as the paper's p0).
  std::vector<int> proposition_of_region;

  static TaskAutomaton make(const ltl::Dfa& dfa, const scenario::World& world);
  // The automaton's state after it reads the region the robot is in (-1: no region).
  int step(int state, int region) const;
};

// The region containing point `p` (the robot's centre), or -1 outside every region. Regions are disjoint.
int region_at(const scenario::World& world, const scenario::Vec2& p);

}  // namespace physltl::planning
