#pragma once
// `bench --sweep key=v1,v2,...` as given: one scenario parameter over several values (campaign.h's Sweep
// holds what each value measured).

#include <string>
#include <vector>

namespace physltl::campaign {

struct SweepSpec {
  std::string key;
  std::vector<std::string> values;
};

// Parses "key=v1,v2,...": a key, then at least two distinct values. Throws BadInput.
SweepSpec parse_sweep(const std::string& text);

}  // namespace physltl::campaign
