#pragma once
// Draws a World in a given state: floor, red fixed bodies, blue movable boxes, green sphere robot, yellow
// regions with their names, soft drop shadows, and an Overlay on top. See docs/rendering.md.
//
// A Renderer owns an OpenGL context; use it from one thread. Output is deterministic: the same inputs give
// the same pixels on the same Mesa.

#include "physltl/render/context.h"
#include "physltl/render/image.h"
#include "physltl/render/scene.h"
#include "physltl/scenario/state.h"
#include "physltl/scenario/world.h"

#include <memory>

namespace physltl::render {

class Renderer {
 public:
  // Loads the World's OBJ meshes and the font, and uploads the static geometry. Throws std::runtime_error
  // (naming the file) when a mesh cannot be read or no OpenGL context can be made.
  Renderer(const scenario::World& world, std::unique_ptr<OffscreenContext> context);
  Renderer(const scenario::World& world, int width, int height);  // an OSMesa context of that size
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  Image draw(const scenario::EnvironmentState& state, const Overlay& overlay, View view);
  // The words of the last picture and where they stand (docs/rendering.md, "The legend" and "Labels").
  const PictureWords& words() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace physltl::render
