#include "physltl/setup/scenario_settings.h"

#include "physltl/common/bad_input.h"
#include "physltl/scenario/load.h"

namespace physltl::setup {

scenario::World load_with_settings(const std::string& path, const std::vector<std::string>& settings) {
  scenario::LoadOptions options;
  for (const auto& setting : settings) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0) throw common::BadInput("--set expects key=value, got '" + setting + "'");
    const auto [at, fresh] = options.params.emplace(setting.substr(0, eq), setting.substr(eq + 1));
    if (!fresh) {
      throw common::BadInput("'" + at->first + "' is set twice: " + at->first + "=" + at->second + " and " + setting);
    }
  }
  return scenario::load_scenario(path, options);
}

}  // namespace physltl::setup
