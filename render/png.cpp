#include "physltl/render/png.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <fstream>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace physltl::render {
namespace {

// Measured on 640x480 frames (render_benchmark, docs/rendering.md). stb treats levels below 5 as 5, its
// fastest; 8 (its default) is ~20% slower for files 0.5% smaller. stb's per-row filter search doubles the
// encoding time for 0.1% smaller files; PNG's "up" filter alone is as fast as none and the smallest of the
// fixed filters on our flat-coloured pictures.
constexpr int kCompressionLevel = 5;
constexpr int kFilter = 2;  // "up"

// stb keeps these settings in globals; set them once, before any thread encodes.
void configure_stb() {
  static std::once_flag once;
  std::call_once(once, [] {
    stbi_write_png_compression_level = kCompressionLevel;
    stbi_write_force_png_filter = kFilter;
  });
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  configure_stb();
  std::vector<std::uint8_t> bytes;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    out->insert(out->end(), static_cast<const std::uint8_t*>(data), static_cast<const std::uint8_t*>(data) + size);
  };
  if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, image.rgb.data(), image.width * 3)) {
    throw std::runtime_error("PNG encoding failed");
  }
  return bytes;
}

void write_png(const Image& image, const std::filesystem::path& path) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

Image read_png(const std::filesystem::path& path) {
  int width = 0, height = 0, channels = 0;
  std::unique_ptr<unsigned char, decltype(&stbi_image_free)> pixels(
      stbi_load(path.c_str(), &width, &height, &channels, 3), &stbi_image_free);
  if (!pixels) throw std::runtime_error("cannot read " + path.string() + ": " + stbi_failure_reason());
  Image image(width, height);
  std::copy(pixels.get(), pixels.get() + image.rgb.size(), image.rgb.begin());
  return image;
}

}  // namespace physltl::render
