#pragma once
// PNG files through stb_image_write / stb_image. The compression settings are fixed (see docs/rendering.md
// for the measurements behind them): stb keeps them in globals, so they cannot vary per call across threads.

#include "physltl/render/image.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace physltl::render {

std::vector<std::uint8_t> encode_png(const Image& image);
// Throws std::runtime_error naming the path when the file cannot be written or read.
void write_png(const Image& image, const std::filesystem::path& path);
Image read_png(const std::filesystem::path& path);  // converted to RGB

}  // namespace physltl::render
