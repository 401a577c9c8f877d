#pragma once
// Command-line arguments shared by every command that reads a scenario.

#include "physltl/scenario/load.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace physltl::app {

struct ScenarioArgs {
  std::string path;
  std::vector<std::string> settings;  // key=value pairs for the script's `params`

  void add_to(CLI::App& app);
  scenario::World load() const;  // throws scenario::ScenarioError or BadInput
};

}  // namespace physltl::app
