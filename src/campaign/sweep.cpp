#include "sweep.h"

#include "physltl/common/bad_input.h"

#include <algorithm>

namespace physltl::campaign {

SweepSpec parse_sweep(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw common::BadInput("--sweep expects key=v1,v2,..., got '" + text + "'");
  SweepSpec spec{text.substr(0, eq), {}};
  const std::string list = text.substr(eq + 1);
  size_t from = 0;
  while (true) {
    const size_t comma = list.find(',', from);
    const std::string value = list.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    if (value.empty()) throw common::BadInput("--sweep: an empty value in '" + text + "'");
    // Values name output folders and log files.
    if (value.find_first_of("/\\") != std::string::npos) {
      throw common::BadInput("--sweep: a value may not contain / or \\, got '" + value + "'");
    }
    if (std::find(spec.values.begin(), spec.values.end(), value) != spec.values.end()) {
      throw common::BadInput("--sweep: " + spec.key + "=" + value + " is given twice");
    }
    spec.values.push_back(value);
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  if (spec.values.size() < 2) throw common::BadInput("--sweep needs at least two values, got '" + text + "'");
  return spec;
}

}  // namespace physltl::campaign
