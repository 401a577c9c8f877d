#pragma once
// Runs units of a campaign one after the other in this process, with progress on a terminal (units done
// of the total and the time left) and Ctrl-C between or inside runs.

#include "bench_case.h"
#include "physltl/campaign/campaign.h"
#include "unit_record.h"

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace physltl::campaign {

struct UnitProgress {
  bool show = false;   // on stderr, when it is a terminal
  std::string label;   // "shard 2/3: " or empty
  size_t done_before = 0;  // units of the total already done (--resume)
  size_t total = 0;
};

// Runs units[i] for each i of `which`, in that order, calling `done` with each result as it ends. Returns
// false when `stop` was raised (the unit it interrupted is not reported).
bool run_units(const std::vector<std::unique_ptr<BenchCase>>& cases, const std::vector<Unit>& units,
               const std::vector<size_t>& which, const CampaignSettings& settings, const UnitProgress& progress,
               const std::atomic<bool>& stop, const std::function<void(const UnitRecord&)>& done);

}  // namespace physltl::campaign
