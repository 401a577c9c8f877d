#pragma once
// Golden-image comparison: decoded pixels against tests/golden/<name>.png, exact match first, then a
// tolerance for other Mesa versions. PHYSLTL_UPDATE_GOLDENS=1 (tests/run --update-goldens) rewrites the
// golden instead of comparing; nothing else ever does.

#include "physltl/render/image.h"

#include <gtest/gtest.h>

#include <string>

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

// On failure writes <name>.actual.png and <name>.diff.png into PHYSLTL_TEST_OUTPUT_DIR and names them.
::testing::AssertionResult matches_golden(const Image& actual, const std::string& name, const Tolerance& tolerance = {});

}  // namespace physltl::render
