#pragma once
// `bench --sweep key=v1,v2,...`: one scenario parameter over several values, every value on the same
// seeds, interleaved so that drift in the machine's speed hits every value alike. How the planning time
// grows with the parameter, as a table, a least-squares line and sweep.json (docs/benchmarks.md).

#include "results.h"
#include "physltl/render/image.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace physltl::app {

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

std::string sweep_table(const Sweep& sweep);
nlohmann::ordered_json sweep_json(const Sweep& sweep);
// sweep.png: each planner's median time against the swept value.
render::Image sweep_chart(const Sweep& sweep);

}  // namespace physltl::app
