#include "physltl/render/preview.h"

#include "physltl/render/png.h"
#include "physltl/render/renderer.h"

namespace physltl::render {

Image draw_preview(const scenario::World& world, const scenario::EnvironmentState& state, const Overlay& overlay) {
  Renderer renderer(world, world.render.width, world.render.height);
  return renderer.draw(state, overlay, world.render.view);
}

void render_preview(const scenario::World& world, const scenario::EnvironmentState& state, const Overlay& overlay,
                    const std::filesystem::path& path) {
  write_png(draw_preview(world, state, overlay), path);
}

}  // namespace physltl::render
