#include "physltl/render/image_compare.h"

#include <algorithm>
#include <cstdlib>

namespace physltl::render {
namespace {

int channel_difference(const Image& a, const Image& b, std::size_t pixel) {
  int largest = 0;
  for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(a.rgb[3 * pixel + c] - b.rgb[3 * pixel + c]));
  return largest;
}

}  // namespace

Comparison compare_images(const Image& expected, const Image& actual, const Tolerance& tolerance) {
  Comparison result;
  result.same_size = expected.width == actual.width && expected.height == actual.height;
  if (!result.same_size) return result;
  if (expected.rgb == actual.rgb) return result;  // the usual case on the Mesa the goldens were made with
  const std::size_t pixels = static_cast<std::size_t>(expected.width) * expected.height;
  std::size_t beyond = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    const int d = channel_difference(expected, actual, i);
    result.largest_difference = std::max(result.largest_difference, d);
    if (d > tolerance.max_channel_difference) ++beyond;
  }
  result.fraction_beyond = static_cast<double>(beyond) / static_cast<double>(pixels);
  return result;
}

Image amplified_difference(const Image& expected, const Image& actual, const Tolerance& tolerance) {
  Image diff(expected.width, expected.height);
  for (std::size_t i = 0; i < diff.rgb.size() / 3; ++i) {
    const int d = channel_difference(expected, actual, i);
    for (int c = 0; c < 3; ++c) {
      const int background = expected.rgb[3 * i + c] / 4;
      const int beyond_colour = c == 1 ? 0 : 255;  // magenta
      diff.rgb[3 * i + c] = static_cast<std::uint8_t>(
          d > tolerance.max_channel_difference ? beyond_colour : std::min(255, background + 16 * d));
    }
  }
  return diff;
}

}  // namespace physltl::render
