#include "physltl/planning/planner_options.h"

#include "physltl/planning/planner_entry.h"

#include <array>
#include <ostream>
#include <utility>

namespace physltl::planning {
namespace {

constexpr std::array<std::pair<StopReason, const char*>, 7> kStopReasonNames{{
    {StopReason::kSolved, "solved"},
    {StopReason::kTimeLimit, "time limit"},
    {StopReason::kInterrupted, "interrupted"},
    {StopReason::kBudget, "budget"},
    {StopReason::kTreeFull, "tree full"},
    {StopReason::kNoLead, "no lead"},
    {StopReason::kNoSolution, "no solution"},
}};

}  // namespace

const std::string& PlannerOptions::parameter(const PlannerParameter& parameter) const {
  const auto given = parameters.find(parameter.name);
  return given != parameters.end() ? given->second : parameter.default_value();
}

long long PlannerStats::own_count(const std::string& name) const {
  const auto kept = own_counts.find(name);
  return kept != own_counts.end() ? kept->second : 0;
}

const char* to_string(StopReason reason) {
  for (const auto& [value, name] : kStopReasonNames) {
    if (value == reason) return name;
  }
  return "no solution";
}

std::optional<StopReason> stop_reason_from(const std::string& text) {
  for (const auto& [value, name] : kStopReasonNames) {
    if (text == name) return value;
  }
  return std::nullopt;
}

StopReason stop_reason_of(const base::Deadline& reached) {
  return reached.interrupted() ? StopReason::kInterrupted : StopReason::kTimeLimit;
}

bool cut_short(StopReason reason) {
  return reason == StopReason::kTimeLimit || reason == StopReason::kTreeFull || reason == StopReason::kBudget;
}

std::ostream& operator<<(std::ostream& out, StopReason reason) { return out << to_string(reason); }

}  // namespace physltl::planning
