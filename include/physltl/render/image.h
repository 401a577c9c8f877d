#pragma once
// A rendered picture in memory: 8-bit RGB, rows from top to bottom (the order PNG and ffmpeg expect).

#include <cstdint>
#include <vector>

namespace physltl::render {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3 bytes

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3) {}
};

}  // namespace physltl::render
