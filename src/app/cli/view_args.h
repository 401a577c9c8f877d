#pragma once
// `--view perspective|top` (run, execute): how the frames and video of a plan look at the world, over the
// scenario's render { view = ... } (docs/rendering.md, "Framing").

#include "physltl/scenario/world.h"

#include <CLI/CLI.hpp>

#include <optional>

namespace physltl::app {

CLI::Option* add_view_option(CLI::App& app, std::optional<scenario::RenderView>& view);

}  // namespace physltl::app
