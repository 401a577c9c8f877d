#pragma once
// A scenario loaded with key=value settings for its script's `params` (--set, a campaign entry's own).

#include "physltl/scenario/world.h"

#include <string>
#include <vector>

namespace physltl::setup {

// Throws BadInput for a setting that is not key=value, scenario::ScenarioError for the scenario's faults.
scenario::World load_with_settings(const std::string& path, const std::vector<std::string>& settings);

}  // namespace physltl::setup
