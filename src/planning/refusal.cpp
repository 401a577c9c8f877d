#include "physltl/planning/refusal.h"

namespace physltl::planning {

const char* refusal_name(Refusal refusal) {
  switch (refusal) {
    case Refusal::kFixedContact: return "fixed_contact";
    case Refusal::kTaskLetter: return "task_letter";
    case Refusal::kWorkspace: return "workspace";
    case Refusal::kLimit: return "limit";
    case Refusal::kImmovableBody: return "immovable_body";
    case Refusal::kPushSide: return "push_side";
    case Refusal::kRouteChoiceCut: return "route_choice_cut";
    case Refusal::kDroppedNode: return "dropped_node";
  }
  return "?";
}

std::optional<Refusal> refusal_of(knowledge::Violation violation) {
  using knowledge::Violation;
  switch (violation) {
    case Violation::kNone: return std::nullopt;
    case Violation::kExceedsRobotLimits: return Refusal::kLimit;
    case Violation::kLeftWorkspace: return Refusal::kWorkspace;
    case Violation::kTouchesFixedBody: return Refusal::kFixedContact;
    case Violation::kTouchesImmovableBody: return Refusal::kImmovableBody;
    case Violation::kPushesFromForbiddenSide: return Refusal::kPushSide;
  }
  return std::nullopt;
}

long long Refusals::total() const {
  long long sum = 0;
  for (long long n : counts) sum += n;
  return sum;
}

std::optional<Refusal> Refusals::most() const {
  std::optional<Refusal> best;
  for (int k = 0; k < kRefusalKinds; ++k) {
    if (counts[static_cast<std::size_t>(k)] > 0 && (!best || counts[static_cast<std::size_t>(k)] > (*this)[*best])) {
      best = static_cast<Refusal>(k);
    }
  }
  return best;
}

Refusals& Refusals::operator+=(const Refusals& other) {
  for (int k = 0; k < kRefusalKinds; ++k) counts[static_cast<std::size_t>(k)] += other.counts[static_cast<std::size_t>(k)];
  return *this;
}

}  // namespace physltl::planning
