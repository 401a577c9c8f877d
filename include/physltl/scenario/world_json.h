#pragma once
// The World as JSON, for `physltl-studio check --json` and report.json.

#include "physltl/scenario/world.h"

#include <nlohmann/json.hpp>

namespace physltl::scenario {

nlohmann::ordered_json to_json(const World& world);

}  // namespace physltl::scenario
