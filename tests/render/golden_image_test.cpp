#include "golden_image.h"

#include <gtest/gtest.h>

namespace physltl::render {
namespace {

Image grey(int width, int height, std::uint8_t level) {
  Image image(width, height);
  std::fill(image.rgb.begin(), image.rgb.end(), level);
  return image;
}

TEST(GoldenComparison, AcceptsIdenticalImages) {
  const Comparison result = compare_images(grey(10, 10, 100), grey(10, 10, 100), {});
  EXPECT_TRUE(result.within({}));
  EXPECT_EQ(result.largest_difference, 0);
}

TEST(GoldenComparison, ToleratesSmallDifferencesEverywhere) {
  const Comparison result = compare_images(grey(10, 10, 100), grey(10, 10, 108), {});
  EXPECT_TRUE(result.within({}));
  EXPECT_EQ(result.largest_difference, 8);
}

TEST(GoldenComparison, RejectsLargeDifferencesInMoreThanTheAllowedFraction) {
  Image changed = grey(100, 40, 100);  // 4000 pixels: 2 may differ (0.05%)
  changed.rgb[0] = 200;
  changed.rgb[3 * 7 + 1] = 0;
  EXPECT_TRUE(compare_images(grey(100, 40, 100), changed, {}).within({}));
  changed.rgb[3 * 9 + 2] = 0;
  const Comparison result = compare_images(grey(100, 40, 100), changed, {});
  EXPECT_FALSE(result.within({}));
  EXPECT_DOUBLE_EQ(result.fraction_beyond, 3.0 / 4000.0);
}

TEST(GoldenComparison, RejectsADifferentSize) {
  EXPECT_FALSE(compare_images(grey(10, 10, 0), grey(10, 11, 0), {}).within({}));
}

TEST(GoldenComparison, DifferenceImageMarksPixelsBeyondToleranceInMagenta) {
  Image changed = grey(2, 1, 100);
  changed.rgb[0] = 200;
  const Image diff = amplified_difference(grey(2, 1, 100), changed, {});
  EXPECT_EQ((std::vector<std::uint8_t>{255, 0, 255, 25, 25, 25}), diff.rgb);
}

}  // namespace
}  // namespace physltl::render
