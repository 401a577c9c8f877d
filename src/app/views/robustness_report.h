#pragma once
// How robustness is shown: in report.json and bench.json as {"worlds", "succeeded", "share",
// "uncertainty", "failures"}, and as one line of the run's summary (docs/robustness.md).

#include "physltl/execution/robustness.h"
#include "physltl/scenario/world.h"

#include <nlohmann/json.hpp>

#include <string>

namespace physltl::app {

nlohmann::ordered_json uncertainty_json(const scenario::Uncertainty& uncertainty);
nlohmann::ordered_json robustness_json(const execution::Robustness& robustness, const scenario::Uncertainty& uncertainty);
// "87/100 perturbed worlds (mass 0.2, friction 0.2, start 0.02 m); failures: push_missed 9, ..."
std::string robustness_line(const execution::Robustness& robustness, const scenario::Uncertainty& uncertainty);

}  // namespace physltl::app
