#include "physltl/planning/stage_graph.h"

#include <deque>

namespace physltl::planning {

namespace {

// Per automaton state, the named parts whose places can change what the automaton does from it or from
// any state it can reach: a part matters at a state when moving it alone changes some step from there.
std::vector<std::uint64_t> relevant_bodies(const TaskAutomaton& task) {
  const knowledge::Labelling& labels = task.labelling;
  const int states = static_cast<int>(task.dfa.size());
  const int named = static_cast<int>(labels.named_parts().size());
  std::vector<std::uint64_t> relevant(static_cast<std::size_t>(states), 0);
  std::vector<std::vector<int>> successors(static_cast<std::size_t>(states));
  for (int q = 0; q < states; ++q) {
    for (int letter = 0; letter < labels.letters(); ++letter) {
      const int next = task.step(q, letter);
      successors[static_cast<std::size_t>(q)].push_back(next);
      const int facts = labels.facts_of(letter), region = labels.robot_region_of(letter);
      for (int i = 0; i < named; ++i) {
        const int places = labels.named_parts()[static_cast<std::size_t>(i)].places();
        for (int place = 0; place < places; ++place) {
          if (task.step(q, labels.letter(labels.with_place(facts, i, place), region)) != next) {
            relevant[static_cast<std::size_t>(q)] |= std::uint64_t{1} << i;
          }
        }
      }
    }
  }
  // What matters at a state matters at every state that can reach it.
  for (bool changed = true; changed;) {
    changed = false;
    for (int q = 0; q < states; ++q) {
      std::uint64_t all = relevant[static_cast<std::size_t>(q)];
      for (int next : successors[static_cast<std::size_t>(q)]) all |= relevant[static_cast<std::size_t>(next)];
      if (all != relevant[static_cast<std::size_t>(q)]) relevant[static_cast<std::size_t>(q)] = all, changed = true;
    }
  }
  return relevant;
}

}  // namespace

StageGraph::StageGraph(const TaskAutomaton& task)
    : task_(task),
      states_(static_cast<int>(task.dfa.size())),
      fact_sets_(task.labelling.fact_sets()),
      relevant_bodies_(relevant_bodies(task)),
      distance_(static_cast<std::size_t>(stages()), -1),
      dead_(task.dfa.size(), true),
      body_move_(static_cast<std::size_t>(stages())) {
  // Distances: breadth first from the accepting stages, backwards over the moves.
  std::vector<std::vector<int>> predecessors(static_cast<std::size_t>(stages()));
  for (int s = 0; s < stages(); ++s) {
    for_each_move(s, [&](int next, const std::optional<BodyMove>&) { predecessors[static_cast<std::size_t>(next)].push_back(s); });
  }
  std::deque<int> todo;
  for (int s = 0; s < stages(); ++s) {
    if (task.dfa.accepting[static_cast<std::size_t>(automaton_state_of(s))]) distance_[static_cast<std::size_t>(s)] = 0, todo.push_back(s);
  }
  while (!todo.empty()) {
    const int s = todo.front();
    todo.pop_front();
    for (int p : predecessors[static_cast<std::size_t>(s)]) {
      if (distance_[static_cast<std::size_t>(p)] < 0) distance_[static_cast<std::size_t>(p)] = distance_[static_cast<std::size_t>(s)] + 1, todo.push_back(p);
    }
  }
  // Which stages need a body moved first: no robot move gets closer, some body move does.
  for (int s = 0; s < stages(); ++s) {
    const int d = distance(s);
    if (d <= 0) continue;
    bool robot_progresses = false;
    std::optional<BodyMove> first_body_move;
    for_each_move(s, [&](int next, const std::optional<BodyMove>& move) {
      if (distance(next) != d - 1) return;
      if (!move) robot_progresses = true;
      else if (!first_body_move) first_body_move = move;
    });
    if (!robot_progresses) body_move_[static_cast<std::size_t>(s)] = first_body_move;
  }
  // Dead automaton states: no accepting state is reachable over any letter at all (any facts at once, not
  // one body at a time as above: physics may move two bodies in one step).
  std::deque<int> alive;
  std::vector<std::vector<int>> before(task.dfa.size());
  for (int q = 0; q < states_; ++q) {
    for (int letter = 0; letter < task.labelling.letters(); ++letter) before[static_cast<std::size_t>(task.step(q, letter))].push_back(q);
    if (task.dfa.accepting[static_cast<std::size_t>(q)]) dead_[static_cast<std::size_t>(q)] = false, alive.push_back(q);
  }
  while (!alive.empty()) {
    const int q = alive.front();
    alive.pop_front();
    for (int p : before[static_cast<std::size_t>(q)]) {
      if (dead_[static_cast<std::size_t>(p)]) dead_[static_cast<std::size_t>(p)] = false, alive.push_back(p);
    }
  }
}

template <class Visit>
void StageGraph::for_each_move(int stage, Visit visit) const {
  const knowledge::Labelling& labels = task_.labelling;
  const int q = automaton_state_of(stage), facts = facts_of(stage);
  for (int region = -1; region < labels.regions(); ++region) {
    visit(this->stage(task_.step(q, labels.letter(facts, region)), facts), std::nullopt);
  }
  for (int named = 0; named < static_cast<int>(labels.named_parts().size()); ++named) {
    const int places = labels.named_parts()[static_cast<std::size_t>(named)].places();
    for (int place = 0; place < places; ++place) {
      if (place == labels.place(facts, named)) continue;
      // The robot pushes it there: it stands by the body, outside the regions (a region is where it goes, or
      // where a body goes, and a body never goes under the robot).
      const int moved = labels.with_place(facts, named, place);
      visit(this->stage(task_.step(q, labels.letter(moved, -1)), moved), BodyMove{named, place});
    }
  }
}

int StageGraph::stage(int automaton_state, int facts) const {
  const std::uint64_t relevant = relevant_bodies_[static_cast<std::size_t>(automaton_state)];
  for (int i = 0; i < static_cast<int>(task_.labelling.named_parts().size()); ++i) {
    if ((relevant >> i & 1) == 0) facts = task_.labelling.with_place(facts, i, 0);
  }
  return facts * states_ + automaton_state;
}

int StageGraph::after_robot(int stage, int region) const {
  const int facts = facts_of(stage);
  return this->stage(task_.step(automaton_state_of(stage), task_.labelling.letter(facts, region)), facts);
}

int StageGraph::after_letter(int stage, int letter) const {
  return this->stage(task_.step(automaton_state_of(stage), letter), task_.labelling.facts_of(letter));
}

}  // namespace physltl::planning
