#include "physltl/setup/uncertainty_args.h"

#include "physltl/common/bad_input.h"
#include "physltl/scenario/load.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <set>

namespace physltl::setup {

scenario::Uncertainty override_uncertainty(const scenario::Uncertainty& declared, const std::string& text) {
  scenario::Uncertainty u = declared;
  std::set<std::string> given;
  size_t from = 0;
  while (from <= text.size()) {
    const size_t comma = text.find(',', from);
    const std::string pair = text.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    const auto eq = pair.find('=');
    double value = 0.0;
    const auto [end, error] = eq == std::string::npos
                                  ? std::from_chars_result{nullptr, std::errc::invalid_argument}
                                  : std::from_chars(pair.data() + eq + 1, pair.data() + pair.size(), value);
    if (eq == std::string::npos || error != std::errc() || end != pair.data() + pair.size() || !std::isfinite(value)) {
      throw common::BadInput(fmt::format("--uncertainty expects key=number,..., got '{}'", pair));
    }
    const std::string key = pair.substr(0, eq);
    double* field = key == "mass"           ? &u.mass
                    : key == "friction"     ? &u.friction
                    : key == "start"        ? &u.start
                    : key == "body_pose"    ? &u.body_pose
                    : key == "body_yaw_deg" ? &u.body_yaw_deg
                                            : nullptr;
    if (field == nullptr) {
      throw common::BadInput(fmt::format("--uncertainty: unknown key '{}' (mass, friction, start, body_pose, body_yaw_deg)", key));
    }
    if (!given.insert(key).second) throw common::BadInput(fmt::format("--uncertainty: {} is given twice", key));
    *field = value;
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  if (const auto problems = scenario::validate_uncertainty(u); !problems.empty()) {
    throw common::BadInput("--uncertainty: " + problems.front().message.substr(problems.front().message.find(':') + 2));
  }
  return u;
}

}  // namespace physltl::setup
