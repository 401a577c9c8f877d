#include "picture_measures.h"

#include <algorithm>
#include <cstdlib>

namespace physltl::render {

PictureMeasures measure_picture(const Image& a, const Image& b) {
  PictureMeasures m;
  const std::uint8_t* corner = b.rgb.data();
  int left = b.width, right = -1, top = b.height, bottom = -1;
  for (int y = 0; y < b.height; ++y) {
    for (int x = 0; x < b.width; ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * b.width + x);
      const bool legend = a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
      const bool drawn = std::abs(b.rgb[i] - corner[0]) + std::abs(b.rgb[i + 1] - corner[1]) + std::abs(b.rgb[i + 2] - corner[2]) >= 6;
      m.legend_pixels += legend;
      m.legend_over_world += legend && drawn;
      if (drawn) left = std::min(left, x), right = std::max(right, x), top = std::min(top, y), bottom = std::max(bottom, y);
    }
  }
  if (right >= left) m.world_width = right - left + 1, m.world_height = bottom - top + 1;
  return m;
}

}  // namespace physltl::render
