#include "lead_search.h"

namespace physltl::planners::knowledge {
namespace {

// Updates between two searches of the whole lead, at least: the part kept meanwhile only steers the
// expansions that go to stages already done (measured: docs/benchmarks.md, "The tree search's constants").
constexpr int kUpdatesPerWholeSearch = 8;

}  // namespace

std::vector<int> LeadSearch::next(int start, int horizon) {
  // A whole search costs in proportion to the stages done, so on a long task it waits until the frontier
  // searches since the last one have cost as much: searching stays a constant share of the planner's work.
  const bool whole_due = updates_since_whole_ >= kUpdatesPerWholeSearch && frontier_work_ >= whole_work_;
  if (!whole_due && horizon == horizon_ && !prefix_.empty() && prefix_.front() == start) {
    const long long before = graph_.lead_work();
    const std::vector<int> frontier_part = graph_.lead(prefix_.back(), horizon);
    frontier_work_ += graph_.lead_work() - before;
    ++updates_since_whole_;
    if (!frontier_part.empty()) {
      std::vector<int> lead(prefix_.begin(), prefix_.end() - 1);
      lead.insert(lead.end(), frontier_part.begin(), frontier_part.end());
      return lead;
    }
  }
  const long long before = graph_.lead_work();
  std::vector<int> lead = graph_.lead(start, horizon);
  whole_work_ = graph_.lead_work() - before;
  horizon_ = horizon;
  frontier_work_ = 0;
  updates_since_whole_ = 1;
  prefix_.clear();
  // The frontier: the stage of the last lead state that holds tree nodes.
  int last = -1;
  for (int i = 0; i < static_cast<int>(lead.size()); ++i) {
    if (!graph_.motions(lead[static_cast<size_t>(i)]).empty()) last = i;
  }
  if (last < 0) return lead;
  const int frontier = graph_.stage_of(lead[static_cast<size_t>(last)]);
  int entry = last;
  while (entry > 0 && graph_.stage_of(lead[static_cast<size_t>(entry - 1)]) == frontier) --entry;
  prefix_.assign(lead.begin(), lead.begin() + entry + 1);
  return lead;
}

}  // namespace physltl::planners::knowledge
