#pragma once
// Several independent planners on one problem, the first validated plan wins (issue 7, "Speed"). Each
// thread has its own search, ODE world and seed stream; the losers stop as soon as a winner is known.
//
// With one thread the planner runs in the calling thread with the run's own seed, so the result equals
// plan() followed by replay(). With more, which thread wins depends on timing: same seed, same set of
// candidate plans, but not necessarily the same winner.

#include "physltl/planning/planner.h"
#include "physltl/planning/replay.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace physltl::planning {

// What a validated plan needs: the search's inputs and the formula replay checks against.
struct Problem {
  const scenario::World& world;
  const TaskAutomaton& task;     // what the search aims at (the simplified formula for the knowledge planner)
  const TaskAutomaton& formula;  // the task as written, which a plan's replay must satisfy
  const knowledge::AbstractKnowledge& knowledge;
  const decomposition::Decomposition& decomposition;
};

// How one racing planner ended: "interrupted" when another thread won first.
struct RacerOutcome {
  std::string stop_reason;
  PlannerStats stats;
};

struct RaceResult {
  // The winner's search when a plan validated; otherwise a search whose plan failed replay (a bug, kept
  // so it can be reported), or else thread 0's.
  PlanResult result;
  std::optional<Replay> replay;            // of result.plan, when it solved
  int winner = -1;                         // the thread whose plan validated
  std::vector<RacerOutcome> racers;        // every thread's search, thread 0 first

  bool solved() const { return replay.has_value() && replay->validated(); }
};

// Plans with `threads` planners (at least 1). options.seed seeds thread 0; options.stop (e.g. Ctrl-C)
// stops every thread.
RaceResult race(const Problem& problem, const PlannerOptions& options, int threads);

// The seed of thread `thread` in a run seeded with `run_seed`: the run seed itself for thread 0, then a
// SplitMix64 stream, so threads explore differently but reproducibly.
std::uint64_t thread_seed(std::uint64_t run_seed, int thread);

}  // namespace physltl::planning
