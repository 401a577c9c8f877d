#pragma once
// The planners' own parameters on a command's line (PlannerEntry::parameters): --NAME VALUE for each the
// program's planners declare, or those of the planners a command can run.

#include "physltl/planning/planner_entry.h"

#include <CLI/CLI.hpp>

#include <map>
#include <string>

namespace physltl::app {

struct PlannerParameterArgs {
  std::map<std::string, std::string> given;  // name -> value, each at its default until the command line says

  // `capability`: only the parameters of planners that have it (execute runs planners that take a budget).
  void add_to(CLI::App& app, planning::Capability planning::Capabilities::*capability = nullptr);
  // Every parameter's value, checked (BadInput).
  std::map<std::string, std::string> values() const;
};

}  // namespace physltl::app
