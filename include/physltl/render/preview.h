#pragma once
// preview.png: what a scenario author wrote, before any planning.

#include "physltl/render/image.h"
#include "physltl/render/scene.h"
#include "physltl/scenario/state.h"
#include "physltl/scenario/world.h"

#include <filesystem>

namespace physltl::render {

// The 3/4 view at the World's render size, with the overlay (e.g. mRegions and a legend with the formula).
Image draw_preview(const scenario::World& world, const scenario::EnvironmentState& state, const Overlay& overlay);
void render_preview(const scenario::World& world, const scenario::EnvironmentState& state, const Overlay& overlay,
                    const std::filesystem::path& path);

}  // namespace physltl::render
