#pragma once
// Why a search refused a step or gave up on a node, counted per search so that a failed search can say
// where its effort went (failed/report.json, docs/report.md). The rules here are semantics: what the task
// or the world forbids, the same for every planner. A planner's own cuts (the knowledge planner's route
// choice and dropped nodes) are its own rules, named by its entry (PlannerEntry::own_refusals), and the
// search widens past them when a stage stalls (docs/planner.md, "Cuts and biases").

#include "physltl/knowledge/validity.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace physltl::planning {

enum class Refusal {
  kFixedContact,    // the robot touched a wall or other fixed body
  kTaskLetter,      // the step's letter takes the automaton where acceptance cannot follow
  kWorkspace,       // the robot or a box left the workspace
  kLimit,           // the robot exceeded its speed or turn rate
  kImmovableBody,   // the robot touched a body kappa types immovable
  kPushSide,        // the robot pushed a constraint-oriented body from outside its active mRegions
  kOverlap,         // two bodies overlapped deeper than the planner's max_overlap
};
inline constexpr int kRefusalKinds = 7;

// The rule's name in report.json and bench.json: "fixed_contact", "task_letter", ...
const char* refusal_name(Refusal refusal);
// The refusal a validity verdict stands for; nothing for a valid step.
std::optional<Refusal> refusal_of(knowledge::Violation violation);

struct Refusals {
  std::array<long long, kRefusalKinds> counts{};
  std::vector<long long> own;  // by the planner's own rules, in its entry's order

  void add(Refusal refusal, long long n = 1) { counts[static_cast<std::size_t>(refusal)] += n; }
  void add_own(int rule, long long n = 1);
  long long operator[](Refusal refusal) const { return counts[static_cast<std::size_t>(refusal)]; }
  long long own_count(int rule) const;
  long long total() const;
  Refusals& operator+=(const Refusals& other);
};

// Every rule's count under its name, the semantic rules first, then `own_names` (the planner's own rules,
// as its entry names them).
std::vector<std::pair<std::string, long long>> named_counts(const Refusals& refused, const std::vector<std::string>& own_names);
// The rule that refused most (the first of equals) with its count; nothing when none refused anything.
std::optional<std::pair<std::string, long long>> most_refused(const Refusals& refused,
                                                              const std::vector<std::string>& own_names);

}  // namespace physltl::planning
