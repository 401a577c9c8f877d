#pragma once
// The task's stages: an automaton state together with where the bodies the task names are (a fact set,
// labelling.h), and how far each stage is from acceptance. From a stage the robot may enter any region,
// which steps the automaton on the letter of that region and the stage's facts; or one body may be pushed
// from one of its places to another by the robot, which then stands outside the regions. A task about the
// robot alone has one fact set, so its stages are its automaton states and their distances the
// automaton's own. The distances guide the search; whether a run can still be accepted at all (dead())
// is decided over every letter, as physics may produce any.
//
// The planner grows its tree stage by stage: where the next move of a shortest way is the robot's, a lead
// through the decomposition guides it (product_graph.h); where it is a body's, the object lead does
// (object_lead.h).

#include "physltl/planning/task.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace physltl::planning {

// A named part (index into Labelling::named_parts: a body or a group) and the place it must get to: 0 out
// of its region sets, k + 1 inside its k-th.
struct BodyMove {
  int named = 0;
  int place = 0;
};

class StageGraph {
 public:
  explicit StageGraph(const TaskAutomaton& task);

  int stages() const { return states_ * fact_sets_; }
  // The stage of an automaton state and the bodies' places, forgetting the places of bodies the task no
  // longer cares about from that state on (once `F(crate@dock & F charger)` has seen the crate in the dock,
  // where it goes next is no stage of the task's).
  int stage(int automaton_state, int facts) const;
  int automaton_state_of(int stage) const { return stage % states_; }
  int facts_of(int stage) const { return stage / states_; }

  // Moves to acceptance, one per region entered or body moved; -1 when none reaches it.
  int distance(int stage) const { return distance_[static_cast<std::size_t>(stage)]; }
  // No accepting state follows from the automaton state over any letter that can occur: whatever the
  // robot and the bodies do next, the task fails. Trees never grow there.
  bool dead(int automaton_state) const { return dead_[static_cast<std::size_t>(automaton_state)]; }
  // The stage the robot reaches by entering `region` (-1: outside every region) from `stage`.
  int after_robot(int stage, int region) const;
  // The stage after a letter the physics produced, from the automaton state of `stage`.
  int after_letter(int stage, int letter) const;
  // When every shortest way from `stage` begins with moving a body: which body to where. Nothing when the
  // robot can make progress on its own, or when the stage is accepting or lost.
  const std::optional<BodyMove>& body_move(int stage) const { return body_move_[static_cast<std::size_t>(stage)]; }

 private:
  template <class Visit>
  void for_each_move(int stage, Visit visit) const;

  const TaskAutomaton& task_;
  int states_;
  int fact_sets_;
  // Per automaton state, the named parts (bit i: Labelling::named_parts()[i]) whose places can still
  // change what the automaton does, from that state or any it can reach.
  std::vector<std::uint64_t> relevant_bodies_;
  std::vector<int> distance_;
  std::vector<bool> dead_;
  std::vector<std::optional<BodyMove>> body_move_;
};

}  // namespace physltl::planning
