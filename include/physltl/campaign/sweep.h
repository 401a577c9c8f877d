#pragma once
// `bench --sweep key=v1,v2,...`: one scenario parameter over several values, every value on the same
// seeds, interleaved so that drift in the machine's speed hits every value alike (docs/benchmarks.md;
// views/sweep_results.h shows how the planning time grows).

#include "physltl/campaign/results.h"

#include <string>
#include <vector>

namespace physltl::campaign {

struct SweepSpec {
  std::string key;
  std::vector<std::string> values;
};

// Parses "key=v1,v2,...": a key, then at least two distinct values. Throws BadInput.
SweepSpec parse_sweep(const std::string& text);

struct SweepPoint {
  std::string value;
  BenchResults results;
};

struct Sweep {
  std::string key;
  std::vector<std::string> settings;  // the --set pairs every value shares
  std::vector<SweepPoint> points;     // in the order the values were given
};

}  // namespace physltl::campaign
