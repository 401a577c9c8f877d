#pragma once
// What the planner must achieve, prepared once per run: the automaton of the (simplified) formula and
// how regions of the World map to its propositions.

#include "physltl/ltl/dfa.h"
#include "physltl/ltl/formula.h"
#include "physltl/scenario/world.h"

#include <vector>

namespace physltl::planning {

struct TaskAutomaton {
  ltl::Formula formula;  // the task the automaton was made from
  ltl::Dfa dfa;
  // For each World region, the index of its proposition in dfa.propositions, or -1 when the formula
  // does not mention it (the region then reads as the paper's p0).
  std::vector<int> proposition_of_region;
  // step(state, region) for every state and region, tabulated: the planner asks after every physics step
  // and for every edge of its lead search. Indexed [state * (regions + 1) + region + 1].
  std::vector<int> successors;

  static TaskAutomaton make(const ltl::Formula& formula, const ltl::Dfa& dfa, const scenario::World& world);
  static TaskAutomaton make(const ltl::Formula& formula, const scenario::World& world);  // translates it
  // Whether a plan must end with the robot and the boxes at rest: tasks read as "stop and stay".
  bool ends_at_rest() const { return dfa.acceptance == ltl::Acceptance::kStopAndStay; }
  // The automaton's state after it reads the region the robot is in (-1: no region).
  int step(int state, int region) const;
};

// Which region contains a point (the robot's centre). The planner asks after every physics step, so each
// region's bounding box is tried before its polygon.
class RegionMap {
 public:
  explicit RegionMap(const scenario::World& world);
  // The region containing `p`, or -1 outside every region. Regions are disjoint.
  int at(const scenario::Vec2& p) const;

 private:
  const scenario::World& world_;
  std::vector<geometry::Rect> bounds_;  // World::regions order
};

}  // namespace physltl::planning
