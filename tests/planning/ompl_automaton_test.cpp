#include "physltl/planning/ompl_automaton.h"

#include "physltl/ltl/parser.h"
#include "physltl/ltl/translate.h"
#include "physltl/scenario/load.h"

#include <gtest/gtest.h>
#include <ompl/control/planners/ltl/Automaton.h>

#include <random>

namespace physltl::planning {
namespace {

// OMPL's automaton steps exactly like ours on every trace a robot can produce.
TEST(OmplAutomaton, AgreesWithTheTaskAutomatonOnRandomRegionTraces) {
  const auto world = scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/rooms.lua");
  for (const char* formula : {"F(p1 & F(p2 & F(p3 | p4)))", "F p1 & F p2 & !p3 U p4", "F(p2 & X F p1)"}) {
    const TaskAutomaton task = TaskAutomaton::make(ltl::parse(formula), world);
    const auto ompl_automaton = to_ompl_automaton(task);
    ASSERT_EQ(ompl_automaton->numStates(), task.dfa.size());
    std::mt19937 random(7);
    for (int trace = 0; trace < 200; ++trace) {
      int ours = task.dfa.start;
      int theirs = ompl_automaton->getStartState();
      for (int step = 0; step < 12; ++step) {
        const int region = static_cast<int>(random() % (world.regions.size() + 1)) - 1;
        ompl::control::World letter(static_cast<unsigned>(world.regions.size()));
        if (region >= 0) letter[static_cast<unsigned>(region)] = true;
        ours = task.step(ours, region);
        theirs = ompl_automaton->step(theirs, letter);
        ASSERT_EQ(theirs, ours) << formula;
        EXPECT_EQ(ompl_automaton->isAccepting(static_cast<unsigned>(theirs)), task.dfa.accepting[ours]);
      }
    }
  }
}

}  // namespace
}  // namespace physltl::planning
