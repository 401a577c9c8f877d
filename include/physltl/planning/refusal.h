#pragma once
// Why a search refused a step or gave up on a node, counted per search so that a failed search can say
// where its effort went (failed/report.json, docs/report.md). The first six are semantics: what the task
// or the world forbids. A route-choice cut and a dropped node are the knowledge planner's heuristics,
// which the search widens past when a stage stalls (docs/planner.md, "Cuts and biases").

#include "physltl/knowledge/validity.h"

#include <array>
#include <optional>

namespace physltl::planning {

enum class Refusal {
  kFixedContact,    // the robot touched a wall or other fixed body
  kTaskLetter,      // the step's letter takes the automaton where acceptance cannot follow
  kWorkspace,       // the robot or a box left the workspace
  kLimit,           // the robot exceeded its speed or turn rate
  kImmovableBody,   // the robot touched a body kappa types immovable
  kPushSide,        // the robot pushed a constraint-oriented body from outside its active mRegions
  kRouteChoiceCut,  // the robot touched a body in a stage whose lead goes round the bodies
  kDroppedNode,     // a node left out after its expansions kept failing at their first step
};
inline constexpr int kRefusalKinds = 8;

// The rule's name in report.json and bench.json: "fixed_contact", "task_letter", ...
const char* refusal_name(Refusal refusal);
// The refusal a validity verdict stands for; nothing for a valid step.
std::optional<Refusal> refusal_of(knowledge::Violation violation);

struct Refusals {
  std::array<long long, kRefusalKinds> counts{};

  void add(Refusal refusal, long long n = 1) { counts[static_cast<std::size_t>(refusal)] += n; }
  long long operator[](Refusal refusal) const { return counts[static_cast<std::size_t>(refusal)]; }
  long long total() const;
  // The rule that refused most (the first of equals); nothing when none refused anything.
  std::optional<Refusal> most() const;
  Refusals& operator+=(const Refusals& other);
};

}  // namespace physltl::planning
