#pragma once
// Comparing a picture with its golden: exact match first, then a tolerance for other Mesa versions, and a
// picture of the differences. The project's own golden tests and `physltl-studio test` share it
// (docs/rendering.md).

#include "physltl/render/image.h"

namespace physltl::render {

// Differences up to 8/255 per channel are rounding in shading and blending. Beyond that, allow 0.05% of the
// pixels (38 at 320x240) for edge pixels another rasteriser may decide the other way; 0.5% let a robot
// drawn blue instead of green pass (docs/rendering.md).
struct Tolerance {
  int max_channel_difference = 8;
  double max_fraction_beyond = 0.0005;
};

struct Comparison {
  bool same_size = false;
  int largest_difference = 0;     // over all channels of all pixels
  double fraction_beyond = 0.0;   // of pixels with a channel differing by more than the tolerance
  bool within(const Tolerance& t) const { return same_size && fraction_beyond <= t.max_fraction_beyond; }
};

Comparison compare_images(const Image& expected, const Image& actual, const Tolerance& tolerance);

// Differences scaled up x16 (and every pixel beyond the tolerance in magenta) on a darkened copy of `expected`.
Image amplified_difference(const Image& expected, const Image& actual, const Tolerance& tolerance);

}  // namespace physltl::render
