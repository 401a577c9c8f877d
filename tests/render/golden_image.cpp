#include "golden_image.h"

#include "physltl/render/png.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace physltl::render {
namespace {

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f%%", 100.0 * fraction);
  return text;
}

bool updating_goldens() {
  const char* value = std::getenv("PHYSLTL_UPDATE_GOLDENS");
  return value != nullptr && std::string(value) == "1";
}

}  // namespace

::testing::AssertionResult matches_golden(const Image& actual, const std::string& name, const Tolerance& tolerance) {
  const std::filesystem::path golden = std::filesystem::path(PHYSLTL_SOURCE_DIR) / "tests/golden" / (name + ".png");
  if (updating_goldens()) {
    // Only a changed picture is rewritten, so an update touches exactly the goldens that moved.
    if (!std::filesystem::exists(golden) || read_png(golden).rgb != actual.rgb) write_png(actual, golden);
    return ::testing::AssertionSuccess() << "updated " << golden;
  }
  if (!std::filesystem::exists(golden)) {
    return ::testing::AssertionFailure() << golden << " is missing; make it with tests/run --update-goldens";
  }
  const Image expected = read_png(golden);
  const Comparison result = compare_images(expected, actual, tolerance);
  if (result.within(tolerance)) return ::testing::AssertionSuccess();

  const std::filesystem::path output(PHYSLTL_TEST_OUTPUT_DIR);
  std::filesystem::create_directories(output);
  const std::filesystem::path actual_path = output / (name + ".actual.png");
  write_png(actual, actual_path);
  auto failure = ::testing::AssertionFailure();
  failure << name << " differs from " << golden << "; actual image: " << actual_path;
  if (!result.same_size) {
    return failure << " (size " << actual.width << "x" << actual.height << ", golden " << expected.width << "x"
                   << expected.height << ")";
  }
  const std::filesystem::path diff_path = output / (name + ".diff.png");
  write_png(amplified_difference(expected, actual, tolerance), diff_path);
  return failure << ", difference (x16, magenta beyond tolerance): " << diff_path << "; "
                 << percent(result.fraction_beyond) << " of pixels differ by more than "
                 << tolerance.max_channel_difference << " (allowed " << percent(tolerance.max_fraction_beyond)
                 << "), largest difference " << result.largest_difference;
}

}  // namespace physltl::render
