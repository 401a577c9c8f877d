#include "view_args.h"

#include <string>
#include <vector>

namespace physltl::app {

CLI::Option* add_view_option(CLI::App& app, std::optional<scenario::RenderView>& view) {
  std::vector<std::string> names;
  for (scenario::RenderView v : scenario::kRenderViews) names.emplace_back(scenario::render_view_name(v));
  return app
      .add_option_function<std::string>(
          "--view", [&view](const std::string& name) { view = scenario::render_view_named(name); },
          "How the frames and video look at the world: perspective or top (default: the scenario's render { view })")
      ->check(CLI::IsMember(names));
}

}  // namespace physltl::app
