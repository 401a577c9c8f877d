#pragma once
// One run of the main job in a process of its own, for what only a whole process can say: its peak
// memory (a process's peak never goes down, so runs sharing one process would each report the largest
// before them) and what each part of the run took (report.json's times_s).

#include "physltl/campaign/campaign.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace physltl::campaign {

struct OwnProcessRequest {
  std::string scenario_file;
  std::string world_name;             // the folder the main job writes into under its --out
  std::vector<std::string> settings;  // key=value, each given as --set
  std::string planner;
  std::uint64_t seed = 0;
  double time_limit_s = 0.0;
  int threads = 1;
  int improve = 0;
  std::map<std::string, std::string> parameters;  // the planners' parameters, each given as --NAME VALUE
  std::optional<std::string> uncertainty;
};

// Runs this program's main job as a child process (writing into a temporary folder, removed after) and
// reads its report.json. Throws Interrupted when a stop came; nothing, with a warning on stderr naming
// why, when the run failed (a fault of the child's: the benchmark's own figures stand).
std::optional<OwnProcessRun> run_in_own_process(const OwnProcessRequest& request);

}  // namespace physltl::campaign
