#include "physltl/execution/robustness.h"

#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/execution/perturbation.h"

#include <algorithm>

namespace physltl::execution {
namespace {

constexpr double kElsewhere = 0.1;  // m

bool saw(const planning::Replay& replay, knowledge::Violation violation) {
  return std::find(replay.violations.begin(), replay.violations.end(), violation) != replay.violations.end();
}

// Why the formula failed: the first of a push that missed, a body that ended elsewhere, or a region not
// reached.
const char* formula_failure(const planning::Replay& run, const planning::Replay& nominal) {
  for (const int body : nominal.moved_bodies) {
    if (std::find(run.moved_bodies.begin(), run.moved_bodies.end(), body) == run.moved_bodies.end()) return "push_missed";
  }
  for (const int body : nominal.moved_bodies) {
    const auto b = static_cast<size_t>(body);
    if ((run.states.back().movable_poses[b].position - nominal.states.back().movable_poses[b].position).norm() > kElsewhere) {
      return "box_elsewhere";
    }
  }
  return "region_not_reached";
}

// The first failure in words, with the step that broke a rule.
std::string describe(const std::string& kind, const planning::Replay& run) {
  const auto first_step = [&](knowledge::Violation v) {
    const auto it = std::find(run.violations.begin(), run.violations.end(), v);
    return it == run.violations.end() ? std::string() : run.violation_messages[static_cast<size_t>(it - run.violations.begin())];
  };
  if (kind == "left_workspace") return first_step(knowledge::Violation::kLeftWorkspace);
  if (kind == "touched_fixed_body") return first_step(knowledge::Violation::kTouchesFixedBody);
  if (kind == "push_missed") return "a body the plan moves did not move";
  if (kind == "box_elsewhere") return "a body the plan moves ended more than 0.1 m from where the plan leaves it";
  if (kind == "region_not_reached") return "the trace does not satisfy the formula";
  if (kind == "not_at_rest") return "the run does not end with the robot and the boxes at rest";
  const std::string limits = first_step(knowledge::Violation::kExceedsRobotLimits);
  return limits.empty() ? "the robot broke a declared limit (speed, turn rate or force)" : limits;
}

}  // namespace

WorldRun judge_in_world(const scenario::World& world, const planning::Plan& plan, const planning::Replay* nominal,
                        const planning::TaskAutomaton& formula, const base::Deadline& deadline) {
  // The truth's own K: its masses decide what kappa calls immovable.
  const knowledge::AbstractKnowledge truth = knowledge::formulate(world);
  // Every planner's plan is judged by every rule, so kappa's count for the baseline's plans too.
  const planning::Replay run = planning::replay(world, plan, formula, truth, {.deadline = deadline});
  WorldRun result;
  if (!run.cut_short.empty()) {
    result.cut_short = true;
    return result;
  }
  auto add = [&](const char* kind) { result.failures.emplace_back(kind); };
  if (!run.accepted) add(nominal != nullptr ? formula_failure(run, *nominal) : "region_not_reached");
  if (saw(run, knowledge::Violation::kLeftWorkspace)) add("left_workspace");
  if (saw(run, knowledge::Violation::kTouchesFixedBody)) add("touched_fixed_body");
  if (!run.within_limits || saw(run, knowledge::Violation::kExceedsRobotLimits)) add("beyond_limits");
  if (!run.ends_at_rest) add("not_at_rest");
  result.succeeded = result.failures.empty();
  // In words, the cause before its consequence: a rule broken at a step before the formula that failed.
  for (const char* kind : {"touched_fixed_body", "left_workspace", "beyond_limits", "push_missed", "box_elsewhere",
                           "region_not_reached", "not_at_rest"}) {
    if (result.first_failure.empty() && std::find(result.failures.begin(), result.failures.end(), kind) != result.failures.end()) {
      result.first_failure = describe(kind, run);
    }
  }
  if (saw(run, knowledge::Violation::kTouchesImmovableBody)) add("touched_immovable_body");
  if (saw(run, knowledge::Violation::kPushesFromForbiddenSide)) add("forbidden_push_side");
  return result;
}

Robustness measure_robustness(const scenario::World& model, const scenario::Uncertainty& uncertainty, int worlds,
                              std::uint64_t seed, const planning::Plan& plan, const planning::Replay& nominal,
                              const planning::TaskAutomaton& formula, const base::Deadline& deadline) {
  Robustness robustness;
  robustness.asked = worlds;
  for (int i = 0; i < worlds; ++i) {
    const WorldRun run = deadline.reached() ? WorldRun{.cut_short = true}
                                            : judge_in_world(perturbed_world(model, uncertainty, seed, i), plan, &nominal, formula, deadline);
    if (run.cut_short) {
      robustness.stopped = deadline.reason();
      break;
    }
    ++robustness.worlds;
    robustness.succeeded += run.succeeded;
    for (const auto& kind : run.failures) ++robustness.failures[kind];
  }
  return robustness;
}

}  // namespace physltl::execution
