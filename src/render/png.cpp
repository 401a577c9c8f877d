#include "physltl/render/png.h"

#include <png.h>

#include <csetjmp>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace physltl::render {
namespace {

// Encoding dominates the cost of a frame, so libpng (zlib) rather than stb's writer: deflate level 1 takes
// ~2 ms per 640x480 frame where stb's fastest setting takes ~13 ms (docs/rendering.md). No row filter: on
// the anti-aliased frames it compresses as small as "up" (43 KB against 44 KB on rooms.lua) and ~20 %
// faster.
constexpr int kCompressionLevel = 1;

// Larger than any picture this program writes (a frame is at most 8,192 pixels a side): a header that
// claims more is refused before its pixels are allocated.
constexpr png_uint_32 kMaxPictureSide = 16384;

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + size);
}

// libpng reports errors by longjmp to here; no C++ object lives in this frame, so nothing is skipped.
bool encode_into(const Image& image, std::vector<std::uint8_t>* bytes) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, bytes, append_bytes, nullptr);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, kCompressionLevel);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  for (int row = 0; row < image.height; ++row) {
    png_write_row(png, image.rgb.data() + static_cast<size_t>(row) * image.width * 3);
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  std::vector<std::uint8_t> bytes;
  if (!encode_into(image, &bytes)) throw std::runtime_error("PNG encoding failed");
  return bytes;
}

void write_png(const Image& image, const std::filesystem::path& path) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

Image read_png(const std::filesystem::path& path) {
  // A pipe or a device named for a picture would be waited on for ever.
  if (!std::filesystem::is_regular_file(path)) throw std::runtime_error("cannot read " + path.string() + ": not a regular file");
  // By content, with libpng: a PNG or nothing. Debian's stb_image decodes every format it knows, whatever
  // the file's name, and spins for ever on a truncated Radiance HDR file (stb_image 2.27).
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  const auto refused = [&](const std::string& why) {
    png_image_free(&png);
    return std::runtime_error("cannot read " + path.string() + ": not a PNG picture this program reads (" + why + ")");
  };
  if (!png_image_begin_read_from_file(&png, path.c_str())) throw refused(png.message);
  if (png.width > kMaxPictureSide || png.height > kMaxPictureSide) {
    throw refused(std::to_string(png.width) + " x " + std::to_string(png.height) + " pixels, over " +
                  std::to_string(kMaxPictureSide) + " a side");
  }
  png.format = PNG_FORMAT_RGB;
  Image image(static_cast<int>(png.width), static_cast<int>(png.height));
  if (!png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr)) throw refused(png.message);
  return image;
}

}  // namespace physltl::render
