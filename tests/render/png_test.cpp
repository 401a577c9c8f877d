#include "physltl/render/png.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace physltl::render {
namespace {

Image gradient(int width, int height) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(i * 7 % 251);
  return image;
}

TEST(Png, RoundTripsPixelsExactly) {
  const std::filesystem::path path = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / "round_trip.png";
  std::filesystem::create_directories(path.parent_path());
  const Image image = gradient(17, 9);
  write_png(image, path);
  const Image read = read_png(path);
  EXPECT_EQ(read.width, 17);
  EXPECT_EQ(read.height, 9);
  EXPECT_EQ(read.rgb, image.rgb);
}

TEST(Png, NamesTheFileItCannotWrite) {
  try {
    write_png(gradient(2, 2), "/nonexistent/folder/x.png");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/folder/x.png"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace physltl::render
