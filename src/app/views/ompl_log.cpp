#include "ompl_log.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <set>

namespace physltl::app {
namespace {

// PlannerStatus::asString() in OMPL 1.5.2, which has no case for ABORT and so names it "Unknown status".
constexpr const char* kStatusNames[] = {"Unknown status", "Invalid start", "Invalid goal", "Unrecognized goal type",
                                        "Timeout", "Approximate solution", "Exact solution", "Crash",
                                        "Unknown status"};

void write_planner(std::ostream& out, const OmplPlannerResults& planner) {
  out << planner.name << "\n";
  out << planner.common.size() << " common properties\n";
  for (const auto& [name, value] : planner.common) out << name << " = " << value << "\n";
  std::set<std::string> properties;  // sorted, as OMPL sorts them
  for (const auto& run : planner.runs) {
    for (const auto& entry : run) properties.insert(entry.first);
  }
  out << properties.size() << " properties for each run\n";
  for (const auto& property : properties) out << property << "\n";
  out << planner.runs.size() << " runs\n";
  for (const auto& run : planner.runs) {
    for (const auto& property : properties) {
      const auto it = run.find(property);
      if (it != run.end()) out << it->second;
      out << "; ";
    }
    out << "\n";
  }
  out << ".\n";
}

// A <<<| ... |>>> block; its text must end its last line for the parser to find |>>>.
void write_block(std::ostream& out, const std::string& text) {
  out << "<<<|\n" << text;
  if (!text.empty() && text.back() != '\n') out << "\n";
  out << "|>>>\n";
}

}  // namespace

void write_ompl_log(std::ostream& out, const OmplExperiment& e) {
  out << "OMPL version 1.5.2\n";
  out << "Experiment " << (e.name.empty() ? "NO_NAME" : e.name) << "\n";
  out << e.parameters.size() << " experiment properties\n";
  for (const auto& [name, value] : e.parameters) out << name << " = " << value << "\n";
  out << "Running on " << (e.host.empty() ? "UNKNOWN" : e.host) << "\n";
  out << "Starting at " << e.start_time << "\n";
  write_block(out, e.setup);
  write_block(out, e.cpu_info);
  out << e.seed << " is the random seed\n";
  out << fmt::format("{} seconds per run\n", e.time_limit_s);
  out << fmt::format("{} MB per run\n", e.memory_limit_mb);
  out << e.run_count << " runs per planner\n";
  out << fmt::format("{} seconds spent to collect the data\n", e.total_duration_s);
  out << "1 enum type\nstatus";
  for (const char* status : kStatusNames) out << '|' << status;
  out << "\n";
  out << e.planners.size() << " planners\n";
  for (const auto& planner : e.planners) write_planner(out, planner);
}

}  // namespace physltl::app
