#pragma once
// How the planning time grows with a swept parameter (campaign/sweep.h): as a table, a least-squares line,
// sweep.json and sweep.png (docs/benchmarks.md).

#include "physltl/campaign/campaign.h"
#include "physltl/render/image.h"

#include <nlohmann/json.hpp>

#include <string>

namespace physltl::app {

std::string sweep_table(const campaign::Sweep& sweep);
nlohmann::ordered_json sweep_json(const campaign::Sweep& sweep);
// sweep.png: each planner's median time against the swept value.
render::Image sweep_chart(const campaign::Sweep& sweep);

}  // namespace physltl::app
