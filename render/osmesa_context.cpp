// OffscreenContext on OSMesa: llvmpipe renders into a buffer we own. With OSMESA_Y_UP off, row 0 of that
// buffer is the top of the picture, so read() is a plain RGBA -> RGB copy.

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
    OSMesaPixelStore(OSMESA_Y_UP, 0);
  }

  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

  int width() const override { return width_; }
  int height() const override { return height_; }

  void make_current() override {
    if (!OSMesaMakeCurrent(context_, rgba_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      throw std::runtime_error("OSMesaMakeCurrent failed");
    }
  }

  unsigned framebuffer() const override { return 0; }  // OSMesa's buffer is the default framebuffer

  void read(Image& image) override {
    glFinish();
    image = Image(width_, height_);
    const std::size_t pixels = static_cast<std::size_t>(width_) * height_;
    for (std::size_t i = 0; i < pixels; ++i) {
      image.rgb[3 * i + 0] = rgba_[4 * i + 0];
      image.rgb[3 * i + 1] = rgba_[4 * i + 1];
      image.rgb[3 * i + 2] = rgba_[4 * i + 2];
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
