#pragma once
// A benchmark's results as a person and the tools read them: the table on stdout, bench.json, bench.png
// and the OMPL benchmark log's experiment (docs/benchmarks.md).

#include "physltl/campaign/campaign.h"
#include "ompl_log.h"
#include "physltl/render/image.h"

#include <nlohmann/json.hpp>

#include <string>

namespace physltl::app {

std::string bench_table(const campaign::BenchResults& results);
nlohmann::ordered_json bench_json(const campaign::BenchResults& results);
// A sweep's run in a process of its own (PlannerRuns::own_process): null without one.
nlohmann::ordered_json own_process_json(const std::optional<campaign::OwnProcessRun>& run);
// bench.png: each planner's run times (log scale) and success.
render::Image bench_chart(const campaign::BenchResults& results);
// host and cpu_info describe the machine; they are the caller's to find out.
OmplExperiment ompl_experiment(const campaign::BenchResults& results, const std::string& host, const std::string& cpu_info);

}  // namespace physltl::app
