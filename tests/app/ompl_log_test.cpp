#include "views/ompl_log.h"

#include <gtest/gtest.h>

#include <sstream>

namespace physltl::app {
namespace {

TEST(OmplLog, WritesTheFormatOfOmpl15BenchmarkLogs) {
  OmplExperiment e;
  e.name = "rooms";
  e.parameters = {{"threads INTEGER", "1"}};
  e.host = "box";
  e.start_time = "2024-01-02 03:04:05";
  e.setup = "physltl-studio bench rooms.lua";  // no final newline: the writer adds it before |>>>
  e.cpu_info = "2 x CPU\n";
  e.seed = 1;
  e.time_limit_s = 60;
  e.memory_limit_mb = 0;
  e.run_count = 2;
  e.total_duration_s = 1.5;
  OmplPlannerResults knowledge;
  knowledge.name = "physltl_knowledge";
  knowledge.common = {{"guidance", "knowledge"}};
  knowledge.runs = {{{"time REAL", "0.25"}, {"solved BOOLEAN", "1"}, {"pushes INTEGER", "3"}},
                    {{"time REAL", "60"}, {"solved BOOLEAN", "0"}}};  // unsolved: no pushes
  e.planners = {knowledge};

  std::ostringstream out;
  write_ompl_log(out, e);
  EXPECT_EQ(out.str(),
            "OMPL version 1.5.2\n"
            "Experiment rooms\n"
            "1 experiment properties\n"
            "threads INTEGER = 1\n"
            "Running on box\n"
            "Starting at 2024-01-02 03:04:05\n"
            "<<<|\nphysltl-studio bench rooms.lua\n|>>>\n"
            "<<<|\n2 x CPU\n|>>>\n"
            "1 is the random seed\n"
            "60 seconds per run\n"
            "0 MB per run\n"
            "2 runs per planner\n"
            "1.5 seconds spent to collect the data\n"
            "1 enum type\n"
            "status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|Approximate solution|"
            "Exact solution|Crash|Unknown status\n"
            "1 planners\n"
            "physltl_knowledge\n"
            "1 common properties\n"
            "guidance = knowledge\n"
            "3 properties for each run\n"
            "pushes INTEGER\n"
            "solved BOOLEAN\n"
            "time REAL\n"
            "2 runs\n"
            "3; 1; 0.25; \n"
            "; 0; 60; \n"
            ".\n");
}

}  // namespace
}  // namespace physltl::app
