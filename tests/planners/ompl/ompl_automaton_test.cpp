#include "ompl_automaton.h"

#include "physltl/ltl/parser.h"
#include "physltl/ltl/translate.h"
#include "physltl/scenario/load.h"

#include <gtest/gtest.h>
#include <ompl/control/planners/ltl/Automaton.h>

#include <limits>
#include <random>
#include <stdexcept>

namespace physltl::planning {
namespace {

using namespace physltl::planners::ompl;

// OMPL's automaton steps exactly like ours on every trace a robot can produce, until ours can no longer
// accept: OMPL's has no transition there (its product prunes such states).
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
        const ompl::control::World letter = region_letter(static_cast<int>(world.regions.size()), region);
        ours = task.step(ours, task.labelling.letter(0, region));
        theirs = ompl_automaton->step(theirs, letter);
        if (theirs < 0) {
          EXPECT_EQ(ompl_automaton->distFromAccepting(static_cast<unsigned>(ours)), std::numeric_limits<unsigned>::max());
          break;
        }
        ASSERT_EQ(theirs, ours) << formula;
        EXPECT_EQ(ompl_automaton->isAccepting(static_cast<unsigned>(theirs)), task.dfa.accepting[ours]);
      }
    }
  }
}

// OMPL steps its automaton at every propagation step but its product graph only when the region changes;
// an automaton that moves on when it reads the same region twice would part the two.
TEST(OmplAutomaton, RefusesAnAutomatonThatMovesOnWhenTheSameRegionIsReadTwice) {
  const auto world = scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/rooms.lua");
  EXPECT_THROW(to_ompl_automaton(TaskAutomaton::make(ltl::parse("p1 & X p1"), world)), std::invalid_argument);
}

}  // namespace
}  // namespace physltl::planning
