#pragma once
// The one place that knows how an OpenGL context without a display is made. Drawing code makes it current
// and draws into framebuffer objects of its own; nothing else. OSMesa is deprecated upstream (gone from
// Mesa 25.1): an EGL surfaceless implementation of this interface can replace it without touching the
// drawing code.

#include <memory>

namespace physltl::render {

class OffscreenContext {
 public:
  virtual ~OffscreenContext() = default;

  // The size of the pictures drawn with it.
  virtual int width() const = 0;
  virtual int height() const = 0;
  // Makes this OpenGL 3.3 core context current on the calling thread.
  virtual void make_current() = 0;
};

// OSMesa (Mesa's llvmpipe on the CPU). Throws std::runtime_error when no 3.3 core context can be made.
std::unique_ptr<OffscreenContext> make_osmesa_context(int width, int height);

}  // namespace physltl::render
