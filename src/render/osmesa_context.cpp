// OffscreenContext on OSMesa. OSMesa needs a client buffer for its default framebuffer even though the
// renderer draws into framebuffer objects of its own; this one is never read.

#include "physltl/render/context.h"

#include <GL/osmesa.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace physltl::render {
namespace {

class OsmesaContext final : public OffscreenContext {
 public:
  OsmesaContext(int width, int height)
      : width_(width), height_(height), rgba_(static_cast<std::size_t>(width) * height * 4) {
    if (width <= 0 || height <= 0) {
      throw std::runtime_error("render size must be positive, got " + std::to_string(width) + "x" +
                               std::to_string(height));
    }
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 24,
                              OSMESA_STENCIL_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context");
    make_current();
  }

  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

  int width() const override { return width_; }
  int height() const override { return height_; }

  void make_current() override {
    if (!OSMesaMakeCurrent(context_, rgba_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      throw std::runtime_error("OSMesaMakeCurrent failed");
    }
  }

 private:
  int width_;
  int height_;
  std::vector<std::uint8_t> rgba_;
  OSMesaContext context_ = nullptr;
};

}  // namespace

std::unique_ptr<OffscreenContext> make_osmesa_context(int width, int height) {
  return std::make_unique<OsmesaContext>(width, height);
}

}  // namespace physltl::render
