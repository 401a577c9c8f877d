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
    case Refusal::kOverlap: return "overlap";
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
    case Violation::kBodiesOverlap: return Refusal::kOverlap;
  }
  return std::nullopt;
}

void Refusals::add_own(int rule, long long n) {
  const auto at = static_cast<std::size_t>(rule);
  if (own.size() <= at) own.resize(at + 1, 0);
  own[at] += n;
}

long long Refusals::own_count(int rule) const {
  const auto at = static_cast<std::size_t>(rule);
  return at < own.size() ? own[at] : 0;
}

long long Refusals::total() const {
  long long sum = 0;
  for (long long n : counts) sum += n;
  for (long long n : own) sum += n;
  return sum;
}

Refusals& Refusals::operator+=(const Refusals& other) {
  for (int k = 0; k < kRefusalKinds; ++k) counts[static_cast<std::size_t>(k)] += other.counts[static_cast<std::size_t>(k)];
  for (std::size_t k = 0; k < other.own.size(); ++k) add_own(static_cast<int>(k), other.own[k]);
  return *this;
}

std::vector<std::pair<std::string, long long>> named_counts(const Refusals& refused, const std::vector<std::string>& own_names) {
  std::vector<std::pair<std::string, long long>> named;
  for (int k = 0; k < kRefusalKinds; ++k) named.emplace_back(refusal_name(static_cast<Refusal>(k)), refused.counts[static_cast<std::size_t>(k)]);
  for (std::size_t k = 0; k < own_names.size(); ++k) named.emplace_back(own_names[k], refused.own_count(static_cast<int>(k)));
  return named;
}

std::optional<std::pair<std::string, long long>> most_refused(const Refusals& refused,
                                                              const std::vector<std::string>& own_names) {
  std::optional<std::pair<std::string, long long>> best;
  for (auto& rule : named_counts(refused, own_names)) {
    if (rule.second > 0 && (!best || rule.second > best->second)) best = std::move(rule);
  }
  return best;
}

}  // namespace physltl::planning
