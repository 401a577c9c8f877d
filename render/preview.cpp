#include "physltl/render/preview.h"

#include "physltl/render/png.h"
#include "physltl/render/renderer.h"

namespace physltl::render {

void render_preview(const scenario::World& world, const scenario::EnvironmentState& state, const Overlay& overlay,
                    const std::filesystem::path& path) {
  Renderer renderer(world, world.render.width, world.render.height);
  write_png(renderer.draw(state, overlay, View::kPerspective), path);
}

}  // namespace physltl::render
